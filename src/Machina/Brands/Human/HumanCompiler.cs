namespace Machina;

/// <summary>Writes a numbered, human-readable listing of the actions (<c>.txt</c>), one line each (line breaks in texts become spaces).</summary>
internal sealed class HumanCompiler : Compiler
{
    internal override RobotType Brand => RobotType.HUMAN;

    internal override string CommentPrefix => "//";

    internal override void Emit(CompileJob job, ProgramOutput output)
    {
        LineSink file = output.OpenFile(job.ProgramName, "txt", RobotProgram.Utf8Bom, CommentPrefix);
        file.AddRange(Header(job));
        file.Add("");
        int index = 0;
        var line = new System.Text.StringBuilder(128);
        // A move's or a turn's description is written straight into the line (AppendDescription), without a string per action.
        job.Replay((action, _) => file.Add(line.Clear().Append('[').Append(index++).Append("] ").AppendDescription(action, oneLine: true)));
    }
}
