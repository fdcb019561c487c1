using System.Globalization;

namespace Machina.Cli.Commands;

/// <summary><c>machina drivers</c>: writes the controller-side driver files with the connection filled in.</summary>
internal static partial class DriversCommand
{
    internal static readonly CliCommand Command = new(
        "drivers",
        "Write the driver files to load on the robot controller",
        """
        Usage: machina drivers abb|ur|kuka --host H --port P --out DIR
               machina drivers abb --install --host H [--port P] [--rws-port N] [--user U] [--max-speed-ratio R]

        Writes the files of Machina's driver, the program that runs on the robot controller and receives the streamed
        actions, with the address and port filled in, and says what to do with them:
          abb   load the driver into the motion task and start it, then "machina run --host H --port P"
          kuka  copy the KRL and EthernetKRL files to the controller, start the driver in T1, then "machina run --host H --port P"
          ur    nothing to load: "machina run" sends the script itself to the robot's script port (30003); the file is
                only for reading

        Options:
          --host H   ABB and KUKA: the address the driver listens on, the controller's own address, e.g. 192.168.125.1
                     (ABB service port) or 127.0.0.1 (RobotStudio's virtual controller); UR: the computer's address
                     the script connects back to (Machina fills it in itself when it sends the script)
          --port P   ABB and KUKA: the port the driver listens on (also P + 1 for the monitor), e.g. 7000 or 54600;
                     UR: the computer's port the script connects back to
          --out DIR  the folder to write into (created if needed)

        With --install (ABB only), nothing is written here: Machina installs the driver on the controller itself through its
        Robot Web Services (RWS 1.0, digest authentication), in automatic mode with the motors on: it uploads the modules to
        $HOME, loads them into T_ROB1 (and T_MACHINA_MONITOR when the controller has that task), resets the program pointer
        and starts RAPID. It refuses, saying why, in a manual mode, with the motors off, with a speed ratio above
        --max-speed-ratio (default 100) or when the FlexPendant holds mastership. See docs/rws.md.
          --port P             the driver's port (default 7000)
          --rws-port N         the controller's Robot Web Services port (default 80)
          --user U             the controller user (default "Default User"); the password is read from the environment
                               variable MACHINA_RWS_PASSWORD (default "robotics")

        Examples:
          machina drivers abb --host 192.168.125.1 --port 7000 --out driver
          machina drivers abb --install --host 192.168.125.1
        """,
        Options: ["--host", "--port", "--out", "--rws-port", "--user", "--max-speed-ratio"],
        Flags: ["--install"],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        RobotType brand = Brands.Parse(args.Single("a brand (abb, ur or kuka)"), Brands.Online, "drivers");
        BrandDefinition definition = BrandRegistry.For(brand);
        string host = args.Required("--host", definition.DriverConnectsBack
            ? $"(this computer's address, which the {definition.DisplayName} driver script connects back to, e.g. 192.168.56.1)"
            : "(the controller's address, e.g. 192.168.125.1)");
        if (args.Has("--install"))
        {
            return await InstallAsync(brand, host, args, context).ConfigureAwait(false);
        }
        int port = args.Port("--port", 0);
        if (port == 0)
        {
            throw new UsageException(definition.DriverConnectsBack
                ? $"machina drivers needs --port P (this computer's port the {definition.DisplayName} driver script connects back to, e.g. 7000). See: machina drivers --help"
                : "machina drivers needs --port P (the port the driver listens on, e.g. 7000). See: machina drivers --help");
        }
        string folder = context.FullPath(args.Required("--out", "DIR (the folder to write the files into)"));
        IReadOnlyDictionary<string, string> files;
        try
        {
            files = Robot.Create("Machina", brand).GetDeviceDriverModules(new Dictionary<string, string>
            {
                ["HOSTNAME"] = host,
                ["PORT"] = port.ToString(CultureInfo.InvariantCulture),
            });
        }
        catch (NotSupportedException)
        {
            throw new CliException($"The {brand} driver is not available in this build yet; these are: " +
                string.Join(", ", BrandRegistry.Online.Where(b => b.DriverNextSteps is not null).Select(b => b.DisplayName)) + ".");
        }
        catch (ArgumentException ex)
        {
            throw new UsageException(Brands.FirstSentences(ex.Message));
        }
        Directory.CreateDirectory(folder);
        foreach ((string fileName, string text) in files.OrderBy(f => f.Key, StringComparer.Ordinal))
        {
            string path = Path.Combine(folder, fileName);
            await File.WriteAllTextAsync(path, text, context.Cancellation).ConfigureAwait(false);
            await context.Stdout.WriteLineAsync(CompileCommand.Display(path, context)).ConfigureAwait(false);
        }
        await context.Stderr.WriteLineAsync(NextSteps(brand, files.Count, host, port)).ConfigureAwait(false);
        return ExitCodes.Ok;
    }

    /// <summary>What the brand really needs once the files are written (docs/getting-started.md, "Load the driver on the controller").</summary>
    internal static string NextSteps(RobotType brand, int fileCount, string host, int port) =>
        (BrandRegistry.For(brand).DriverNextSteps ?? throw new ArgumentOutOfRangeException(nameof(brand), brand, "This brand has no driver."))(fileCount, host, port);
}
