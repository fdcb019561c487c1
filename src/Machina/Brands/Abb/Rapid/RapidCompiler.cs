namespace Machina;

/// <summary>
/// Writes ABB RAPID: a <c>.pgf</c> program file naming one module, and the <c>.mod</c> module with its declarations
/// (tooldata, speeddata, zonedata, optional target constants) and <c>PROC main()</c> holding one or more lines per action.
/// </summary>
internal sealed class RapidCompiler : Compiler
{
    internal override RobotType Brand => RobotType.ABB;

    internal override string CommentPrefix => "!";

    internal override void Emit(CompileJob job, ProgramOutput output)
    {
        RapidPlan plan = RapidPlan.Collect(job);

        LineSink pgf = output.OpenFile(job.ProgramName, "pgf", RobotProgram.Ascii, CommentPrefix);
        pgf.Add("<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>");
        pgf.Add("<Program>");
        pgf.Add($"    <Module>{job.ProgramName}.mod</Module>");
        pgf.Add("</Program>");

        LineSink mod = output.OpenFile(job.ProgramName, "mod", RobotProgram.Ascii, CommentPrefix);
        mod.Add("MODULE " + plan.ModuleName);
        mod.Add("");
        mod.AddRange(Header(job));
        mod.Add("");
        if (plan.UsesIO)
        {
            mod.Add("  ! This program sets IO signals: each signal name must exist in the controller's IO configuration.");
            mod.Add("");
        }
        AddBlock(mod, plan.DataLines, "");
        AddBlock(mod, plan.CustomDeclarations, "  ");

        var writer = new RapidWriter(job, plan, mod);
        if (!job.Options.InlineTargets && writer.DeclareTargets() > 0)
        {
            mod.Add("");
        }
        mod.Add("  PROC main()");
        mod.Add("    ConfJ \\Off;");
        mod.Add("    ConfL \\Off;");
        mod.Add(writer.StartAcceleration());
        mod.Add("");
        writer.WriteInstructions();
        mod.Add("");
        mod.Add("  ENDPROC");
        mod.Add("");
        mod.Add("ENDMODULE");
    }

    private static void AddBlock(LineSink sink, List<string> lines, string indent)
    {
        if (lines.Count == 0)
        {
            return;
        }
        foreach (string line in lines)
        {
            sink.Add(indent + line);
        }
        sink.Add("");
    }
}
