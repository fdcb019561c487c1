namespace Machina;

/// <summary>Writes Machina's own instruction text (<c>.machina</c>), which <c>Robot.Do</c> and <c>Instructions.Parse</c> read back.</summary>
internal sealed class MachinaCompiler : Compiler
{
    internal override RobotType Brand => RobotType.MACHINA;

    internal override string CommentPrefix => "//";

    internal override RobotProgram Compile(CompileJob job)
    {
        var lines = new List<string>(job.Actions.Count + 8);
        lines.AddRange(Header(job));
        lines.Add("");
        job.Replay((action, _) => lines.Add(action.ToInstruction()));
        var file = new RobotProgramFile(job.ProgramName, "machina", RobotProgram.Utf8Bom, CommentPrefix, lines);
        return new RobotProgram(job.ProgramName, Brand, [file], job.Warnings);
    }
}
