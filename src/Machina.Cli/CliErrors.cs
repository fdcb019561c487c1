namespace Machina.Cli;

/// <summary>The exit codes of the machina command.</summary>
internal static class ExitCodes
{
    /// <summary>Everything worked.</summary>
    internal const int Ok = 0;

    /// <summary>The program or the robot failed: a malformed or refused instruction, a check that found problems, a lost connection, a disk error.</summary>
    internal const int Failed = 1;

    /// <summary>The command line itself is wrong (unknown option, missing value, unknown brand…).</summary>
    internal const int Usage = 2;

    /// <summary>Stopped with Ctrl+C (128 + SIGINT, as shells report it).</summary>
    internal const int Cancelled = 130;
}

/// <summary>A mistake on the command line; the message says what to type instead.</summary>
internal sealed class UsageException(string message) : Exception(message);

/// <summary>A failure to report to the user as one clear sentence (no stack trace), with its exit code.</summary>
internal sealed class CliException(string message, int exitCode = ExitCodes.Failed) : Exception(message)
{
    /// <summary>The exit code the command ends with.</summary>
    internal int ExitCode { get; } = exitCode;

    /// <summary>True when the message already starts with where the problem is (<c>file:line:column: error: …</c>).</summary>
    internal bool IsLocated { get; init; }

    /// <summary>A problem at a place in a program file, written the way compilers write them: <c>square.machina:3:5: error: …</c>.</summary>
    internal static CliException At(string file, int line, int column, string problem) =>
        new($"{file}:{line}:{column}: error: {problem}") { IsLocated = true };
}
