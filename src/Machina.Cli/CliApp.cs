using Machina.Cli.Commands;

namespace Machina.Cli;

/// <summary>The machina command line: finds the command, reads its arguments, runs it and turns failures into clear messages and exit codes.</summary>
internal static class CliApp
{
    /// <summary>Every command, in the order "machina --help" lists them.</summary>
    internal static readonly CliCommand[] Commands =
    [
        CompileCommand.Command,
        CheckCommand.Command,
        PreviewCommand.Command,
        RunCommand.Command,
        SimCommand.Command,
        DriversCommand.Command,
        ModelsCommand.Command,
        VerifyCommand.Command,
        BridgeCommand.Command,
    ];

    /// <summary>The version printed by "machina --version".</summary>
    internal static string Version => $"machina {LibraryInfo.Version} (Machina library {Robot.Version}, .NET {Environment.Version})";

    internal static string Help => $"""
        machina - program robots from the command line with Machina ({LibraryInfo.Version})

        Usage: machina COMMAND [arguments] [options]

        Commands:
        {string.Join(Environment.NewLine, Commands.Select(c => $"  {c.Name,-9} {c.Summary}"))}

        A PROGRAM is a text file of Machina instructions, one per line, for example:
            SpeedTo(100);
            MoveTo(400, 300, 500);
            Move(0, 0, -50);
            Wait(500);
        Distances are in millimetres, angles in degrees, speeds in mm/s, times in milliseconds.

        Try:
          machina compile square.machina --brand abb --out build
          machina run square.machina --brand abb --sim
          machina preview square.machina --out square.html
        Run "machina COMMAND --help" for the options of a command, "machina --version" for the version.
        """;

    /// <summary>Runs the command line with the console streams given (tests pass string writers).</summary>
    internal static Task<int> RunAsync(string[] args, TextReader stdin, TextWriter stdout, TextWriter stderr, CancellationToken cancellationToken) =>
        RunAsync(args, new CliContext(stdin, stdout, stderr, cancellationToken));

    /// <summary>Runs the command line in <paramref name="context"/> and returns the exit code; never throws.</summary>
    internal static async Task<int> RunAsync(string[] args, CliContext context)
    {
        ArgumentNullException.ThrowIfNull(args);
        if (args.Length == 0 || args[0] is "--help" or "-h" or "-?" or "help")
        {
            if (args.Length >= 2 && args[0] == "help")
            {
                return await RunAsync([args[1], "--help"], context).ConfigureAwait(false);
            }
            await context.Stdout.WriteLineAsync(Help).ConfigureAwait(false);
            return args.Length == 0 ? ExitCodes.Usage : ExitCodes.Ok;
        }
        if (args[0] is "--version" or "-v" or "version")
        {
            await context.Stdout.WriteLineAsync(Version).ConfigureAwait(false);
            return ExitCodes.Ok;
        }
        CliCommand? command = Commands.FirstOrDefault(c => c.Name == args[0].ToLowerInvariant());
        if (command is null)
        {
            string? close = Commands.Select(c => c.Name).FirstOrDefault(n => n.StartsWith(args[0], StringComparison.OrdinalIgnoreCase) && args[0].Length >= 2);
            await context.Stderr.WriteLineAsync($"machina: error: \"{args[0]}\" is not a machina command." +
                (close is not null ? $" Did you mean \"{close}\"?" : "") + " Run \"machina --help\" to see the commands.").ConfigureAwait(false);
            return ExitCodes.Usage;
        }
        string[] rest = args[1..];
        if (rest.Any(a => a is "--help" or "-h" or "-?"))
        {
            await context.Stdout.WriteLineAsync(command.Help).ConfigureAwait(false);
            return ExitCodes.Ok;
        }
        try
        {
            CliArgs parsed = CliArgs.Parse(command.Name, rest, command.Options, command.Flags);
            return await command.Run(parsed, context).ConfigureAwait(false);
        }
        catch (UsageException ex)
        {
            await context.Stderr.WriteLineAsync("machina: error: " + ex.Message).ConfigureAwait(false);
            return ExitCodes.Usage;
        }
        catch (CliException ex)
        {
            // A failure's message can quote a controller's words (bytes from the wire): printable, escape codes as \x1b.
            string message = PrintableText.Of(ex.Message, keepLines: true);
            await context.Stderr.WriteLineAsync(ex.IsLocated ? message : "machina: error: " + message).ConfigureAwait(false);
            return ex.ExitCode;
        }
        catch (OperationCanceledException) when (context.Cancellation.IsCancellationRequested)
        {
            await context.Stderr.WriteLineAsync("machina: stopped (Ctrl+C).").ConfigureAwait(false);
            return ExitCodes.Cancelled;
        }
        catch (MachinaException ex)
        {
            await context.Stderr.WriteLineAsync("machina: error: the robot link failed: " + PrintableText.Of(ex.Message, keepLines: true)).ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            await context.Stderr.WriteLineAsync("machina: error: " + ex.Message).ConfigureAwait(false);
            return ExitCodes.Failed;
        }
    }
}
