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
        if (job.Options.InlineTargets)
        {
            // One pass: the instructions go to a spool while the declarations are gathered, then the module is written
            // around them. Only when names collide (which the provisional names cannot foresee) is it done again in two.
            RapidPlan live = RapidPlan.StartLive(job);
            using SpoolSink body = output.OpenSpool(RobotProgram.Ascii);
            new RapidWriter(job, live, body).WriteInstructions();
            live.Finish();
            if (live.ProvisionalNamesHeld)
            {
                WriteModule(job, output, live, writer => body.MoveTo(writer.Sink));
                return;
            }
            job.Restart();
        }
        WriteModule(job, output, RapidPlan.Collect(job), writer => writer.WriteInstructions());
    }

    /// <summary>Writes the program file and the module, with the instructions from <paramref name="instructions"/>.</summary>
    private void WriteModule(CompileJob job, ProgramOutput output, RapidPlan plan, Action<RapidWriter> instructions)
    {
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
        AddBlock(mod, ReadDeclarations(plan), "  ");

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
        instructions(writer);
        mod.Add("");
        mod.Add("  ENDPROC");
        mod.Add("");
        mod.Add("ENDMODULE");
    }

    /// <summary>The variables ReadDigital and ReadAnalog store their value in (DInput returns a dionum, AInput a num).</summary>
    private static List<string> ReadDeclarations(RapidPlan plan)
    {
        var lines = new List<string>(2);
        if (plan.ReadsDigital)
        {
            lines.Add("VAR dionum machina_di := 0;");
        }
        if (plan.ReadsAnalog)
        {
            lines.Add("VAR num machina_ai := 0;");
        }
        return lines;
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
