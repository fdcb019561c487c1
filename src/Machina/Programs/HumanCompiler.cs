namespace Machina;

/// <summary>Writes a numbered, human-readable listing of the actions (<c>.txt</c>).</summary>
internal sealed class HumanCompiler : Compiler
{
    internal override RobotType Brand => RobotType.HUMAN;

    internal override string CommentPrefix => "//";

    internal override RobotProgram Compile(CompileJob job)
    {
        var lines = new List<string>(job.Actions.Count + 8);
        lines.AddRange(Header(job));
        lines.Add("");
        int index = 0;
        job.Replay((action, _) => lines.Add($"[{index++}] {action.Describe()}"));
        var file = new RobotProgramFile(job.ProgramName, "txt", RobotProgram.Utf8Bom, CommentPrefix, lines);
        return new RobotProgram(job.ProgramName, Brand, [file], job.Warnings);
    }
}
