using System.Globalization;

namespace Machina.Cli.Commands;

/// <summary><c>machina drivers</c>: writes the controller-side driver files with the connection filled in.</summary>
internal static class DriversCommand
{
    internal static readonly CliCommand Command = new(
        "drivers",
        "Write the driver files to load on the robot controller",
        """
        Usage: machina drivers abb|ur|kuka --host H --port P --out DIR

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

        Example:
          machina drivers abb --host 192.168.125.1 --port 7000 --out driver
        """,
        Options: ["--host", "--port", "--out"],
        Flags: [],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        RobotType brand = Brands.Parse(args.Single("a brand (abb, ur or kuka)"), [RobotType.ABB, RobotType.UR, RobotType.KUKA], "drivers");
        string host = args.Required("--host", "(the controller's address, e.g. 192.168.125.1)");
        int port = args.Port("--port", 0);
        if (port == 0)
        {
            throw new UsageException("machina drivers needs --port P (the port the driver listens on, e.g. 7000). See: machina drivers --help");
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
            throw new CliException($"The {brand} driver is not available in this build yet; ABB's is.");
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
    internal static string NextSteps(RobotType brand, int fileCount, string host, int port) => brand switch
    {
        RobotType.ABB => $"Wrote {fileCount} ABB driver files for {host}:{port}. With RobotStudio or the FlexPendant, load machina_abb_driver.mod " +
            $"into the motion task T_ROB1 and start it in manual reduced speed: it listens on {host}:{port}. For live positions, load " +
            $"machina_abb_monitor.mod into a second task, T_MACHINA_MONITOR (Multitasking option 623-1); it uses port {port + 1}. " +
            $"Then: machina run PROGRAM --brand abb --host {host} --port {port}",
        RobotType.KUKA => $"Wrote {fileCount} KUKA driver files for {host}:{port} (needs the KUKA.EthernetKRL option). Copy the .xml files to " +
            @"C:\KRC\ROBOTER\Config\User\Common\EthernetKRL and the .src and .dat files to R1\Program; for live positions add " +
            $"machina_kuka_monitor( ) to the USER PLC fold of sps.sub (it uses port {port + 1}; flags 1 to 3 and timer 16 must be free). " +
            $"Select machina_kuka_driver and start it in T1: it listens on {host}:{port}. Then: machina run PROGRAM --brand kuka --host {host} --port {port}",
        RobotType.UR => $"Wrote {fileCount} UR driver file{(fileCount == 1 ? "" : "s")} for reading, filled in with {host}:{port} as the computer it connects back to. " +
            "Nothing to load on a UR: machina run sends this script to the robot's script port itself, with this computer's address " +
            "and a free port filled in. Give the robot a fixed address the computer can reach (and that can reach the computer), put " +
            "an e-Series robot in remote control, then: machina run PROGRAM --brand ur --host ROBOT_ADDRESS --port 30003",
        _ => throw new ArgumentOutOfRangeException(nameof(brand), brand, "Only ABB, KUKA and UR have drivers."),
    };
}
