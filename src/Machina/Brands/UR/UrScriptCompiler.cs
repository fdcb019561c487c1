namespace Machina;

/// <summary>
/// Writes URScript for Universal Robots: one <c>.script</c> file defining a function that holds the program (custom
/// declarations, optional target variables, one or more lines per action), followed by a call to that function.
/// </summary>
internal sealed class UrScriptCompiler : Compiler
{
    internal override RobotType Brand => RobotType.UR;

    internal override string CommentPrefix => "#";

    internal override void Emit(CompileJob job, ProgramOutput output)
    {
        string function = UrScriptText.FunctionName(job.ProgramName);
        var script = new WarningRuns(output.OpenFile(job.ProgramName, "script", RobotProgram.Ascii, CommentPrefix), "  # ");
        script.AddRange(Header(job));
        script.Add("");
        script.Add("def " + function + "():");
        script.Add("");

        bool anyDeclaration = false;
        foreach (string statement in job.CustomDeclarations)
        {
            script.Add("  " + statement);
            anyDeclaration = true;
        }
        if (anyDeclaration)
        {
            script.Add("");
        }

        var writer = new UrScriptWriter(job, script);
        if (!job.Options.InlineTargets && writer.DeclareTargets() > 0)
        {
            script.Add("");
        }
        writer.WriteStartTool();
        writer.WriteInstructions();
        script.Add("");
        script.Add("end");
        script.Add("");
        script.Add(function + "()");
    }
}
