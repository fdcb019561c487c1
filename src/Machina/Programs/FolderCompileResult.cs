namespace Machina;

/// <summary>What <see cref="Instructions.CompileToFolder(string, RobotType, string, CompileOptions?, string?, string, RobotModel?, CancellationToken)"/> wrote: the files and the warnings.</summary>
public sealed class FolderCompileResult
{
    internal FolderCompileResult(string programName, RobotType language, IReadOnlyList<string> paths, IReadOnlyList<ProgramWarning> warnings, int warningCount, int actionCount)
    {
        WarningCount = warningCount;
        ProgramName = programName;
        Language = language;
        Paths = paths;
        Warnings = warnings;
        ActionCount = actionCount;
    }

    /// <summary>The program's name as written in the files (made safe for robot languages).</summary>
    public string ProgramName { get; }

    /// <summary>The language the files are written in.</summary>
    public RobotType Language { get; }

    /// <summary>Full paths of the files written, in the order they should be loaded.</summary>
    public IReadOnlyList<string> Paths { get; }

    /// <summary>
    /// What the device could not do exactly as asked, each with the line and column of its instruction (<see cref="ProgramWarning.Line"/>, <see cref="ProgramWarning.Column"/>):
    /// the first <see cref="Instructions.MaxWarningsKept"/>, so that memory stays small; <see cref="WarningCount"/> counts them all.
    /// Each warning is also written as a comment in the program.
    /// </summary>
    public IReadOnlyList<ProgramWarning> Warnings { get; }

    /// <summary>How many warnings the compilation raised in all (may exceed <see cref="Warnings"/>.Count).</summary>
    public int WarningCount { get; }

    /// <summary>Number of actions (statements) read from the instructions.</summary>
    public int ActionCount { get; }

    /// <summary>Text such as <c>HelloRobot (ABB): 2 files, 1204 actions, 0 warnings</c>.</summary>
    public override string ToString() => $"{ProgramName} ({Language}): {Counted.Of(Paths.Count, "file")}, {Counted.Of(ActionCount, "action")}, {Counted.Of(WarningCount, "warning")}";
}
