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
        WriteProgramFile(job, output);
        LineSink mod = output.OpenFile(job.ProgramName, "mod", RobotProgram.Ascii, CommentPrefix);
        if (job.Options.InlineTargets)
        {
            if (TryWriteForeseen(job, mod))
            {
                return;
            }
            // One pass: the instructions go to a spool while the declarations are gathered, then the module is written
            // around them. Only when names collide (which the provisional names cannot foresee) is it done again in two.
            RapidPlan live = RapidPlan.StartLive(job);
            using SpoolSink body = output.OpenSpool(RobotProgram.Ascii);
            new RapidWriter(job, live, body).WriteInstructions();
            live.Finish();
            if (live.ProvisionalNamesHeld)
            {
                WriteModule(job, mod, live, _ => body.MoveTo(mod));
                return;
            }
            job.Restart();
        }
        WriteModule(job, mod, RapidPlan.Collect(job), writer => writer.WriteInstructions());
    }

    /// <summary>
    /// Writes the module in one pass straight into its file, without a spool, when its declarations can be foreseen: an
    /// instruction text that names nothing that declares (<see cref="RapidPlan.WordsThatDeclare"/>) but <c>SpeedTo(number)</c>
    /// moves at the start's zone and tool and at the speeds its text names (<see cref="RapidSpeedScan"/>), so its declarations
    /// are foreseen (<see cref="RapidPlan.Foresee(CompileJob, RapidSpeedScan)"/>). The
    /// declarations met while writing are checked against those at the end; when they differ (a text without motions) the file
    /// is started over and false returned. A 10^6-line program's body (130-170 MB of RAPID) is then written once instead of
    /// twice (to the spool, then from it into the module).
    /// </summary>
    private bool TryWriteForeseen(CompileJob job, LineSink mod)
    {
        if (job.Source is null || !mod.CanStartOver || RapidSpeedScan.Of(job.Source) is not RapidSpeedScan scan)
        {
            return false;
        }
        RapidPlan foreseen = RapidPlan.Foresee(job, scan);
        RapidPlan live = RapidPlan.StartLive(job);
        WriteModule(job, mod, foreseen, _ => new RapidWriter(job, live, mod).WriteInstructions());
        live.Finish();
        if (live.ProvisionalNamesHeld && live.DeclaresAs(foreseen))
        {
            return true;
        }
        mod.StartOver();
        job.Restart();
        return false;
    }

    /// <summary>The program file, naming the module.</summary>
    private void WriteProgramFile(CompileJob job, ProgramOutput output)
    {
        LineSink pgf = output.OpenFile(job.ProgramName, "pgf", RobotProgram.Ascii, CommentPrefix);
        pgf.Add("<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>");
        pgf.Add("<Program>");
        pgf.Add($"    <Module>{job.ProgramName}.mod</Module>");
        pgf.Add("</Program>");
    }

    /// <summary>Writes the module into <paramref name="mod"/>, with the instructions from <paramref name="instructions"/>.</summary>
    private void WriteModule(CompileJob job, LineSink mod, RapidPlan plan, Action<RapidWriter> instructions)
    {
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
