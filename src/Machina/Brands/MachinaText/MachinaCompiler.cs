namespace Machina;

/// <summary>Writes Machina's own instruction text (<c>.machina</c>), which <c>Robot.Do</c> and <c>Instructions.Parse</c> read back.</summary>
internal sealed class MachinaCompiler : Compiler
{
    internal override RobotType Brand => RobotType.MACHINA;

    internal override string CommentPrefix => "//";

    internal override void Emit(CompileJob job, ProgramOutput output)
    {
        LineSink file = output.OpenFile(job.ProgramName, "machina", RobotProgram.Utf8Bom, CommentPrefix);
        file.AddRange(Header(job));
        file.Add("");
        job.Replay((action, _) => file.Add(action.ToInstruction()));
    }
}
