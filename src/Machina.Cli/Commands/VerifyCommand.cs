using Machina.Cli.Programs;
using Machina.Cli.Twins;
using Machina.Simulation.Twin;

namespace Machina.Cli.Commands;

/// <summary><c>machina verify</c>: runs a compiled URScript or RAPID program on a twin controller and checks where the arm got.</summary>
internal static class VerifyCommand
{
    internal static readonly CliCommand Command = new(
        "verify",
        "Run a compiled UR, ABB or KUKA program on a twin controller and compare it with the library",
        """
        Usage: machina verify PROGRAM --brand ur|abb|kuka [--script FILE] [--model M] [--max-steps N]

        PROGRAM is a text file of Machina instructions. It is compiled to URScript (or FILE, a URScript program compiled from
        it earlier, is taken instead), and the script runs on the URScript twin: a controller that interprets URScript as
        described in UR's Script Manual, with the arm model's kinematics. Each pose the arm reached and each output it set
        is compared with the library's own trace of the instructions, step by step; each step is listed with its line in
        PROGRAM, or "not reached" when the program stopped before it. A program the controller would refuse
        (an unknown function, a wrong argument) or stop (an unreachable pose, a joint limit) fails with the controller's
        message. The arm starts at the first motion's target.

        PROGRAM may also be a .script file alone: it then runs on the twin and each step is listed, with no comparison.

        With --brand abb the program is compiled to RAPID and its main runs on the RAPID twin, which interprets RAPID
        (modules, data, routines, error handlers, motion, IO) with the arm model's kinematics. --script is then the
        compiled RAPID program: a .pgf file, a .mod file or a folder holding them. PROGRAM may also be such a
        .pgf/.mod file or folder alone: main runs and each step is listed.

        With --brand kuka the program is compiled to KRL and its main routine runs on the KRL twin, which interprets KRL
        (.src routines, .dat data lists, motion in $BASE/$TOOL, software limit switches, outputs) with the arm model's
        kinematics. --script is then the compiled KRL program: a .src file (its .dat beside it is loaded too) or a folder.
        PROGRAM may also be such a .src file or folder alone: its main routine runs and each step is listed.

        Options:
          --brand ur|abb|kuka  the controller (UR: URScript twin; ABB: RAPID twin; KUKA: KRL twin)
          --script FILE      the compiled program to check, instead of compiling PROGRAM now
          --model M          the arm model (default UR5e for UR, IRB 120 for ABB, KR 6 R900 sixx for KUKA; machina models lists them)
          --max-steps N      the statements the program may run before it is stopped as endless (default 50,000,000);
                             the other budgets (nesting, calls, arrays, strings, file size) are in docs/simulation.md, "Limits"

        Examples:
          machina verify square.machina --brand ur
          machina verify square.machina --brand abb --model "IRB 1200-5/0.9"
          machina verify out/Square --brand abb
          machina verify square.machina --brand kuka
        Exit code: 0 when the program runs to its end and every step agrees, 1 when it does not, 2 for a command-line mistake.
        """,
        Options: ["--brand", "--script", "--model", "--max-steps"],
        Flags: [],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string path = args.Single("a PROGRAM file (Machina instructions, a .script, or a RAPID .pgf/.mod file or folder)");
        RobotType brand = Brands.Parse(args.Required("--brand", $"({Or(TwinPrograms.Brands.Select(Brands.Name))}: the brands with a twin controller)"), TwinPrograms.Brands);
        ITwinProgram twin = TwinPrograms.For(brand);
        RobotModel model = Brands.Model(args.Value("--model") ?? twin.Brand.DefaultModel, brand)!;
        TwinLimits limits = VerifyLimits(args);
        if (twin.IsProgram(context.FullPath(path)) && args.Value("--script") is null)
        {
            return await RunAloneAsync(twin, ReadFiles(twin, context, path), path, model, limits, context).ConfigureAwait(false);
        }
        (List<RobotAction> actions, Func<RobotAction, int?> lineOf) = ReadProgram(path, context);
        IReadOnlyList<(string Name, string Text)> files = args.Value("--script") is { } compiled
            ? ReadFiles(twin, context, compiled)
            : [.. Compilers.For(brand).Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model }).Files
                .Where(twin.Loads).Select(f => (f.FileName, f.ToText("\n")))];
        TextWriter output = context.Stdout;
        await output.WriteLineAsync($"Running {(args.Value("--script") ?? "the compiled program")} on a {twin.Language} twin of {twin.Article} {model} and comparing it with {path}.").ConfigureAwait(false);
        TwinCheck result = twin.Verify(files, actions, model, limits, context.Cancellation);
        await output.WriteAsync(result.ToText(lineOf)).ConfigureAwait(false);
        return result.Passed ? ExitCodes.Ok : ExitCodes.Failed;
    }

    /// <summary>A compiled program run on the twin with nothing to compare it with: each step it makes, and how it ended.</summary>
    private static async Task<int> RunAloneAsync(ITwinProgram twin, IReadOnlyList<(string Name, string Text)> files, string path, RobotModel model, TwinLimits limits, CliContext context)
    {
        TextWriter output = context.Stdout;
        TwinRun run = twin.Run(files, model, limits, context.Cancellation);
        if (run.LoadError is not null)
        {
            await output.WriteLineAsync($"FAILED: {run.LoadError}").ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        await output.WriteLineAsync($"Ran {path} on a {twin.Language} twin of {twin.Article} {model}, from {twin.JointsWord} {run.StartJoints}.").ConfigureAwait(false);
        foreach (TwinTraceEntry step in run.Trace)
        {
            await output.WriteLineAsync(FormattableString.Invariant(
                $"  line {step.Line,-5} {step.Seconds,9:0.000} s  {step.Text}: TCP {step.Tcp.Position}, joints {step.Joints}")).ConfigureAwait(false);
        }
        await output.WriteLineAsync(run.Finished
            ? FormattableString.Invariant($"OK: the program ran to its end in {run.Seconds:0.###} s")
            : $"FAILED: {run.Error ?? "the program was stopped"}").ConfigureAwait(false);
        return run.Finished ? ExitCodes.Ok : ExitCodes.Failed;
    }

    /// <summary>"a, b or c".</summary>
    private static string Or(IEnumerable<string> names)
    {
        string[] all = [.. names];
        return all.Length < 2 ? string.Concat(all) : string.Join(", ", all[..^1]) + " or " + all[^1];
    }

    /// <summary>The twin's budgets for a verification: the default ones, with the step budget of <c>--max-steps</c>.</summary>
    private static TwinLimits VerifyLimits(CliArgs args)
    {
        if (args.Value("--max-steps") is not { } text)
        {
            return TwinLimits.Verify;
        }
        return long.TryParse(text, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out long steps) && steps > 0
            ? TwinLimits.Verify with { MaxSteps = steps }
            : throw new CliException($"--max-steps must be a whole number above 0, not \"{text}\"", ExitCodes.Usage);
    }

    /// <summary>The text of a program file, refused before it is read when it is larger than the twins take.</summary>
    private static string ReadProgramText(string fullPath)
    {
        long most = TwinLimits.Default.MaxProgramChars;
        return new FileInfo(fullPath).Length > most
            ? throw new IOException($"the file is larger than {most} bytes, the most a twin loads")
            : File.ReadAllText(fullPath);
    }

    /// <summary>The program's actions, and the line of the file each one came from (the report numbers the file's lines, not the compiled program's).</summary>
    private static (List<RobotAction> Actions, Func<RobotAction, int?> LineOf) ReadProgram(string path, CliContext context)
    {
        var statements = new List<InstructionStatement>();
        using (ProgramReader reader = ProgramReader.Open(path, context, null))
        {
            try
            {
                statements.AddRange(reader.Read(context.Cancellation));
            }
            catch (InstructionParseException ex)
            {
                throw CliException.At(reader.DisplayName, ex.Line, ex.Column, ex.Problem);
            }
        }
        var lines = new Dictionary<RobotAction, int>(ReferenceEqualityComparer.Instance);
        foreach (InstructionStatement s in statements)
        {
            lines.TryAdd(s.Action, s.Line);
        }
        return ([.. statements.Select(s => s.Action)], a => lines.TryGetValue(a, out int line) ? line : null);
    }

    /// <summary>The files of the compiled program at <paramref name="path"/> (a file or a folder), each refused when larger than the twins take.</summary>
    private static List<(string Name, string Text)> ReadFiles(ITwinProgram twin, CliContext context, string path)
    {
        try
        {
            return [.. twin.ProgramFiles(context.FullPath(path)).Select(f => (Path.GetFileName(f), ReadProgramText(f)))];
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or System.Xml.XmlException)
        {
            throw new CliException(twin.ProgramNoun is { } noun ? $"Cannot read {noun} \"{path}\": {ex.Message}" : $"Cannot read \"{path}\": {ex.Message}");
        }
    }
}
