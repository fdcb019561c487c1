using Machina.Cli.Programs;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Cli.Commands;

/// <summary><c>machina verify</c>: runs a compiled URScript or RAPID program on a twin controller and checks where the arm got.</summary>
internal static partial class VerifyCommand
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
        // The brands with a twin controller: URScript and RAPID.
        BrandDefinition twinBrand = UrBrand.Definition;
        RobotType brand = Brands.Parse(args.Required("--brand", "(ur, abb or kuka: the brands with a twin controller)"), [twinBrand.Type, AbbBrand.Definition.Type, KukaBrand.Definition.Type]);
        if (brand == AbbBrand.Definition.Type)
        {
            return await RunAbbAsync(path, args, context).ConfigureAwait(false);
        }
        if (brand == KukaBrand.Definition.Type)
        {
            return await RunKukaAsync(path, args, context).ConfigureAwait(false);
        }
        RobotModel model = Brands.Model(args.Value("--model") ?? twinBrand.DefaultModel, twinBrand.Type)!;
        var options = new UrTwinOptions { Model = model, Limits = VerifyLimits(args) };
        TextWriter output = context.Stdout;
        if (path.EndsWith(".script", StringComparison.OrdinalIgnoreCase) && args.Value("--script") is null)
        {
            return await RunAloneAsync(ReadFile(context, path), path, options, context).ConfigureAwait(false);
        }
        (List<RobotAction> actions, Func<RobotAction, int?> lineOf) = ReadProgram(path, context);
        string script = args.Value("--script") is { } scriptPath
            ? ReadFile(context, scriptPath)
            : twinBrand.CreateCompiler().Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model }).Files[0].ToText("\n");
        await output.WriteLineAsync($"Running {(args.Value("--script") ?? "the compiled program")} on a URScript twin of a {model} and comparing it with {path}.").ConfigureAwait(false);
        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify(script, actions, options, context.Cancellation);
        await output.WriteAsync(result.ToText(lineOf)).ConfigureAwait(false);
        return result.Passed ? ExitCodes.Ok : ExitCodes.Failed;
    }

    private static async Task<int> RunAloneAsync(string script, string path, UrTwinOptions options, CliContext context)
    {
        using var twin = new UrTwinController(options);
        UrProgramState state = twin.Run(script, context.Cancellation);
        await context.Stdout.WriteLineAsync($"Ran {path} on a URScript twin of a {options.Model}, from joints {options.StartJoints}.").ConfigureAwait(false);
        foreach (Machina.Simulation.Twin.TwinTraceEntry step in twin.Arm.Trace)
        {
            await context.Stdout.WriteLineAsync(FormattableString.Invariant(
                $"  line {step.Line,-5} {step.Seconds,9:0.000} s  {step.Text}: TCP {step.Tcp.Position}, joints {step.Joints}")).ConfigureAwait(false);
        }
        await context.Stdout.WriteLineAsync(state == UrProgramState.Finished
            ? FormattableString.Invariant($"OK: the program ran to its end in {twin.Clock.Seconds:0.###} s")
            : $"FAILED: {twin.Error ?? "the program was stopped"}").ConfigureAwait(false);
        return state == UrProgramState.Finished ? ExitCodes.Ok : ExitCodes.Failed;
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

    private static string ReadFile(CliContext context, string path)
    {
        try
        {
            return ReadProgramText(context.FullPath(path));
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot read \"{path}\": {ex.Message}");
        }
    }
}
