namespace Machina.Cli;

/// <summary>
/// What a command talks to: standard input, output and error, whether output is an interactive terminal, the clock, the
/// folder relative paths start from, and the token that Ctrl+C cancels. Tests build one around string writers.
/// </summary>
internal sealed class CliContext
{
    /// <summary>Creates a context; <paramref name="workingDirectory"/> defaults to the process's current folder.</summary>
    internal CliContext(TextReader stdin, TextWriter stdout, TextWriter stderr, CancellationToken cancellation,
        bool isTerminal = false, TimeProvider? time = null, string? workingDirectory = null)
    {
        Stdin = stdin;
        Stdout = stdout;
        Stderr = stderr;
        Cancellation = cancellation;
        IsTerminal = isTerminal;
        Time = time ?? TimeProvider.System;
        WorkingDirectory = workingDirectory ?? Directory.GetCurrentDirectory();
    }

    /// <summary>Standard input (a program given as "-").</summary>
    internal TextReader Stdin { get; }

    /// <summary>Standard output: results (written paths, reports).</summary>
    internal TextWriter Stdout { get; }

    /// <summary>Standard error: warnings, errors and progress.</summary>
    internal TextWriter Stderr { get; }

    /// <summary>Cancelled by Ctrl+C.</summary>
    internal CancellationToken Cancellation { get; }

    /// <summary>True when the output is a terminal a person watches (progress bars), false when redirected (plain lines).</summary>
    internal bool IsTerminal { get; }

    /// <summary>The clock for rates and timings.</summary>
    internal TimeProvider Time { get; }

    /// <summary>The folder relative paths are resolved from.</summary>
    internal string WorkingDirectory { get; }

    /// <summary>An absolute path for a path given on the command line.</summary>
    internal string FullPath(string path) => Path.GetFullPath(path, WorkingDirectory);

    /// <summary>Writes "machina: warning: …" to standard error.</summary>
    internal void Warn(string message) => Stderr.WriteLine("machina: warning: " + message);

    /// <summary>Called by long-running commands once they are ready (e.g. a virtual controller listening); tests wait on it.</summary>
    internal Action<string>? Ready { get; init; }
}
