using Machina.Cli.Programs;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Cli.Commands;

/// <summary><c>machina verify … --brand kuka</c>: the KRL twin.</summary>
internal static partial class VerifyCommand
{
    private static async Task<int> RunKukaAsync(string path, CliArgs args, CliContext context)
    {
        RobotModel model = Brands.Model(args.Value("--model") ?? KukaBrand.Definition.DefaultModel, KukaBrand.Definition.Type)!;
        var options = new KrlTwinOptions { Model = model, Limits = VerifyLimits(args) };
        TextWriter output = context.Stdout;
        if (IsKrl(context.FullPath(path)) && args.Value("--script") is null)
        {
            return await RunKrlAloneAsync(path, options, context).ConfigureAwait(false);
        }
        (List<RobotAction> actions, Func<RobotAction, int?> lineOf) = ReadProgram(path, context);
        List<(string Name, string Text)> files = args.Value("--script") is { } compiled
            ? ReadKrl(context, compiled)
            : [.. Compilers.For(KukaBrand.Definition.Type).Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model }).Files
                .Where(f => f.Extension.Equals("src", StringComparison.OrdinalIgnoreCase) || f.Extension.Equals("dat", StringComparison.OrdinalIgnoreCase)).Select(f => (f.FileName, f.ToText("\n")))];
        await output.WriteLineAsync($"Running {(args.Value("--script") ?? "the compiled program")} on a KRL twin of a {model} and comparing it with {path}.").ConfigureAwait(false);
        TwinVerification<KrlProgramState> result = KrlVerifier.Verify(files, actions, options, context.Cancellation);
        await output.WriteAsync(result.ToText(lineOf)).ConfigureAwait(false);
        return result.Passed ? ExitCodes.Ok : ExitCodes.Failed;
    }

    private static bool IsKrl(string fullPath) => fullPath.EndsWith(".src", StringComparison.OrdinalIgnoreCase)
        || (Directory.Exists(fullPath) && Directory.GetFiles(fullPath, "*.src").Length > 0);

    private static List<(string Name, string Text)> ReadKrl(CliContext context, string path)
    {
        try
        {
            return [.. KrlTwinController.ProgramFiles(context.FullPath(path)).Select(f => (Path.GetFileName(f), ReadProgramText(f)))];
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"Cannot read the KRL program \"{path}\": {ex.Message}");
        }
    }

    private static async Task<int> RunKrlAloneAsync(string path, KrlTwinOptions options, CliContext context)
    {
        List<(string Name, string Text)> files = ReadKrl(context, path);
        using var twin = new KrlTwinController(options);
        TextWriter output = context.Stdout;
        try
        {
            twin.Load([.. files]);
        }
        catch (KrlLoadException ex)
        {
            await output.WriteLineAsync($"FAILED: {ex.Message}").ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        KrlProgramState state = twin.Run(null, context.Cancellation);
        await output.WriteLineAsync($"Ran {path} on a KRL twin of a {options.Model}, from axes {options.StartJoints}.").ConfigureAwait(false);
        foreach (TwinTraceEntry step in twin.Arm.Trace)
        {
            await output.WriteLineAsync(FormattableString.Invariant(
                $"  line {step.Line,-5} {step.Seconds,9:0.000} s  {step.Text}: TCP {step.Tcp.Position}, joints {step.Joints}")).ConfigureAwait(false);
        }
        await output.WriteLineAsync(state == KrlProgramState.Finished
            ? FormattableString.Invariant($"OK: the program ran to its end in {twin.Clock.Seconds:0.###} s")
            : $"FAILED: {twin.Error ?? "the program was stopped"}").ConfigureAwait(false);
        return state == KrlProgramState.Finished ? ExitCodes.Ok : ExitCodes.Failed;
    }
}
