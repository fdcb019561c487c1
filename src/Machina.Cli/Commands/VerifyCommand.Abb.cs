using Machina.Cli.Programs;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Cli.Commands;

/// <summary><c>machina verify … --brand abb</c>: the RAPID twin.</summary>
internal static partial class VerifyCommand
{
    private static async Task<int> RunAbbAsync(string path, CliArgs args, CliContext context)
    {
        RobotModel model = Brands.Model(args.Value("--model") ?? AbbBrand.Definition.DefaultModel, AbbBrand.Definition.Type)!;
        var options = new RapidTwinOptions { Model = model, Limits = VerifyLimits(args) };
        TextWriter output = context.Stdout;
        if (IsRapid(context.FullPath(path)) && args.Value("--script") is null)
        {
            return await RunRapidAloneAsync(path, options, context).ConfigureAwait(false);
        }
        (List<RobotAction> actions, Func<RobotAction, int?> lineOf) = ReadProgram(path, context);
        List<(string Name, string Text)> modules = args.Value("--script") is { } compiled
            ? ReadRapid(context, compiled)
            : [.. Compilers.For(AbbBrand.Definition.Type).Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model }).Files
                .Where(f => f.Extension.Equals("mod", StringComparison.OrdinalIgnoreCase)).Select(f => (f.FileName, f.ToText("\n")))];
        await output.WriteLineAsync($"Running {(args.Value("--script") ?? "the compiled program")} on a RAPID twin of an {model} and comparing it with {path}.").ConfigureAwait(false);
        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(modules, actions, options, context.Cancellation);
        await output.WriteAsync(result.ToText(lineOf)).ConfigureAwait(false);
        return result.Passed ? ExitCodes.Ok : ExitCodes.Failed;
    }

    private static bool IsRapid(string fullPath) => Directory.Exists(fullPath)
        || fullPath.EndsWith(".pgf", StringComparison.OrdinalIgnoreCase) || fullPath.EndsWith(".mod", StringComparison.OrdinalIgnoreCase);

    private static List<(string Name, string Text)> ReadRapid(CliContext context, string path)
    {
        try
        {
            return [.. RapidTwinController.ModuleFiles(context.FullPath(path)).Select(f => (Path.GetFileName(f), ReadProgramText(f)))];
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or System.Xml.XmlException)
        {
            throw new CliException($"Cannot read the RAPID program \"{path}\": {ex.Message}");
        }
    }

    private static async Task<int> RunRapidAloneAsync(string path, RapidTwinOptions options, CliContext context)
    {
        List<(string Name, string Text)> modules = ReadRapid(context, path);
        var twin = new RapidTwinController(options);
        TextWriter output = context.Stdout;
        try
        {
            twin.Load([.. modules]);
        }
        catch (RapidLoadException ex)
        {
            await output.WriteLineAsync($"FAILED: {ex.Module}: {ex.Message}").ConfigureAwait(false);
            return ExitCodes.Failed;
        }
        RapidProgramState state = twin.Run("main", context.Cancellation);
        await output.WriteLineAsync($"Ran {path} on a RAPID twin of an {options.Model}, from joints {options.StartJoints}.").ConfigureAwait(false);
        foreach (Machina.Simulation.Twin.TwinTraceEntry step in twin.Arm.Trace)
        {
            await output.WriteLineAsync(FormattableString.Invariant(
                $"  line {step.Line,-5} {step.Seconds,9:0.000} s  {step.Text}: TCP {step.Tcp.Position}, joints {step.Joints}")).ConfigureAwait(false);
        }
        await output.WriteLineAsync(state == RapidProgramState.Finished
            ? FormattableString.Invariant($"OK: the program ran to its end in {twin.Clock.Seconds:0.###} s")
            : $"FAILED: {twin.Error ?? "the program was stopped"}").ConfigureAwait(false);
        return state == RapidProgramState.Finished ? ExitCodes.Ok : ExitCodes.Failed;
    }
}
