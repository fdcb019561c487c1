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
        actions, with the controller's address and port filled in. Load them on the controller and start them before
        "machina run --host H --port P".

        Options:
          --host H   the address the driver listens on: the controller's own address, e.g. 192.168.125.1
                     (ABB service port) or 127.0.0.1 (RobotStudio's virtual controller)
          --port P   the port the driver listens on (ABB: also P + 1 for the monitor), e.g. 7000
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
        await context.Stderr.WriteLineAsync($"Wrote {files.Count} {brand} driver files for {host}:{port}. Load them on the controller and start them, " +
            $"then: machina run PROGRAM --brand {Brands.Name(brand)} --host {host} --port {port}").ConfigureAwait(false);
        return ExitCodes.Ok;
    }
}
