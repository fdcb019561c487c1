using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>
/// One brand's twin controller as the command line runs programs on it (<c>machina verify</c>, <c>machina sim BRAND --load</c>):
/// the per-brand part of those commands, so that the commands themselves are one path for every brand (<see cref="TwinPrograms"/>).
/// </summary>
internal interface ITwinProgram
{
    /// <summary>The brand whose controller the twin imitates.</summary>
    BrandDefinition Brand { get; }

    /// <summary>The language the twin runs, as messages name it (e.g. "RAPID").</summary>
    string Language { get; }

    /// <summary>The article messages put before a model of the brand ("a UR5e", "an IRB 120").</summary>
    string Article { get; }

    /// <summary>What the brand calls the arm's joint values in messages ("joints", "axes").</summary>
    string JointsWord { get; }

    /// <summary>How a read error names the program: "the RAPID program" (null: the path alone).</summary>
    string? ProgramNoun { get; }

    /// <summary>True when <paramref name="fullPath"/> is a compiled program of the language (a file or a folder) rather than Machina instructions.</summary>
    bool IsProgram(string fullPath);

    /// <summary>The files of the compiled program at <paramref name="fullPath"/> (a file or a folder), in the order the twin loads them.</summary>
    IReadOnlyList<string> ProgramFiles(string fullPath);

    /// <summary>True for a compiled file the twin loads (e.g. RAPID's .mod files, not the .pgf).</summary>
    bool Loads(RobotProgramFile file);

    /// <summary>Runs the program's files on a twin of <paramref name="model"/> and compares each step with <paramref name="actions"/>.</summary>
    TwinCheck Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, RobotModel model, TwinLimits limits, CancellationToken cancellation);

    /// <summary>Runs the program's files (main) on a twin of <paramref name="model"/>, from the twin's start joints.</summary>
    TwinRun Run(IReadOnlyList<(string Name, string Text)> files, RobotModel model, TwinLimits limits, CancellationToken cancellation);

    /// <summary>
    /// <c>machina sim BRAND --load …</c>: runs the compiled programs the arguments name on the twin in real time, telling what it does,
    /// and returns the exit code; null when the brand's twin loads no programs from the command line. The address is the
    /// command's <c>--bind</c>, as it parsed and checked it.
    /// </summary>
    Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded { get; }

    /// <summary>
    /// The options of <c>machina sim BRAND --load</c> that <see cref="RunLoaded"/> reads besides <c>--load</c> and <c>--model</c>: any
    /// other option given with --load is refused, never ignored.
    /// </summary>
    IReadOnlyList<string> LoadOptions { get; }

    /// <summary>True when <c>--load</c> may be given more than once (one program per task).</summary>
    bool LoadsSeveral { get; }
}

/// <summary>A verification's outcome: whether it passed, and its report with the steps named by the line <c>lineOf</c> gives.</summary>
/// <param name="Passed">True when the program ran to its end and every step agrees.</param>
/// <param name="ToText">The report, given the source line of each action.</param>
internal sealed record TwinCheck(bool Passed, Func<Func<RobotAction, int?>, string> ToText);

/// <summary>A program run alone on a twin.</summary>
/// <param name="LoadError">Why the controller refused to load the program (then it did not run), or null.</param>
/// <param name="Finished">True when the program ran to its end.</param>
/// <param name="Error">The controller's error, or null.</param>
/// <param name="Trace">Each step the arm made.</param>
/// <param name="Seconds">Program time, in seconds.</param>
/// <param name="StartJoints">The joints the arm started from.</param>
internal sealed record TwinRun(string? LoadError, bool Finished, string? Error, IReadOnlyList<TwinTraceEntry> Trace, double Seconds, Joints StartJoints)
{
    /// <summary>A program the controller refused to load.</summary>
    internal static TwinRun Refused(string error) => new(error, false, error, [], 0, default);
}
