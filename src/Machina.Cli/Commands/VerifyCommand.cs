using Machina.Cli.Programs;
using Machina.Simulation.UrScript;

namespace Machina.Cli.Commands;

/// <summary><c>machina verify</c>: runs a compiled URScript program on the URScript twin controller and checks where the arm got.</summary>
internal static class VerifyCommand
{
    internal static readonly CliCommand Command = new(
        "verify",
        "Run a compiled UR program on a twin controller and compare it with the library",
        """
        Usage: machina verify PROGRAM --brand ur [--script FILE] [--model M]

        PROGRAM is a text file of Machina instructions. It is compiled to URScript (or FILE, a URScript program compiled from
        it earlier, is taken instead), and the script runs on the URScript twin: a controller that interprets URScript as
        described in UR's Script Manual, with the arm model's kinematics. Each pose the arm reached and each output it set
        is compared with the library's own trace of the instructions, line by line. A program the controller would refuse
        (an unknown function, a wrong argument) or stop (an unreachable pose, a joint limit) fails with the controller's
        message. The arm starts at the first motion's target.

        PROGRAM may also be a .script file alone: it then runs on the twin and each step is listed, with no comparison.

        Options:
          --brand ur         the controller (only UR has a twin so far)
          --script FILE      the compiled URScript to check, instead of compiling PROGRAM now
          --model M          the arm model (default UR5e; machina models lists them)

        Example:
          machina verify square.machina --brand ur
        Exit code: 0 when the program runs to its end and every step agrees, 1 when it does not, 2 for a command-line mistake.
        """,
        Options: ["--brand", "--script", "--model"],
        Flags: [],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string path = args.Single("a PROGRAM file (Machina instructions, or a .script)");
        // The URScript twin is the only twin controller so far: its brand is the one --brand must name.
        BrandDefinition twinBrand = UrBrand.Definition;
        Brands.Parse(args.Required("--brand", "(ur: only UR has a twin controller so far)"), [twinBrand.Type]);
        RobotModel model = Brands.Model(args.Value("--model") ?? twinBrand.DefaultModel, twinBrand.Type)!;
        var options = new UrTwinOptions { Model = model };
        TextWriter output = context.Stdout;
        if (path.EndsWith(".script", StringComparison.OrdinalIgnoreCase) && args.Value("--script") is null)
        {
            return await RunAloneAsync(ReadFile(context, path), path, options, context).ConfigureAwait(false);
        }
        List<RobotAction> actions = [];
        using (ProgramReader reader = ProgramReader.Open(path, context, null))
        {
            try
            {
                actions.AddRange(reader.Read(context.Cancellation).Select(s => s.Action));
            }
            catch (InstructionParseException ex)
            {
                throw CliException.At(reader.DisplayName, ex.Line, ex.Column, ex.Problem);
            }
        }
        string script = args.Value("--script") is { } scriptPath
            ? ReadFile(context, scriptPath)
            : twinBrand.CreateCompiler().Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model }).Files[0].ToText("\n");
        await output.WriteLineAsync($"Running {(args.Value("--script") ?? "the compiled program")} on a URScript twin of a {model} and comparing it with {path}.").ConfigureAwait(false);
        UrVerification result = UrScriptVerifier.Verify(script, actions, options, context.Cancellation);
        await output.WriteAsync(result.ToText()).ConfigureAwait(false);
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

    private static string ReadFile(CliContext context, string path)
    {
        try
        {
            return File.ReadAllText(context.FullPath(path));
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot read \"{path}\": {ex.Message}");
        }
    }
}
