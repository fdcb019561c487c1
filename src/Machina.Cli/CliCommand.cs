namespace Machina.Cli;

/// <summary>One command of the machina tool: its name, one-line summary, help text, the options it knows and what it does.</summary>
/// <param name="Name">What is typed after "machina".</param>
/// <param name="Summary">One line for "machina --help".</param>
/// <param name="Help">The text of "machina NAME --help".</param>
/// <param name="Options">Options that take a value.</param>
/// <param name="Flags">Options without a value.</param>
/// <param name="Run">Runs the command; returns the exit code.</param>
internal sealed record CliCommand(string Name, string Summary, string Help, string[] Options, string[] Flags, Func<CliArgs, CliContext, Task<int>> Run);
