using Machina.Cli.Commands;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>The KRL twin: a .src file (with its .dat) or a folder, whose main routine runs.</summary>
internal sealed class KrlTwinProgram : ITwinProgram
{
    public BrandDefinition Brand => KukaBrand.Definition;

    public string Language => "KRL";

    public string Article => "a";

    public string JointsWord => "axes";

    public string? ProgramNoun => "the KRL program";

    public Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded { get; } =
        (args, model, _, context) => SimCommand.RunKrlAsync(args.Value("--load")!, model, context);

    public bool IsProgram(string fullPath) => fullPath.EndsWith(".src", StringComparison.OrdinalIgnoreCase)
        || (Directory.Exists(fullPath) && Directory.GetFiles(fullPath, "*.src").Length > 0);

    public IReadOnlyList<string> ProgramFiles(string fullPath) => KrlTwinController.ProgramFiles(fullPath);

    public bool Loads(RobotProgramFile file) =>
        file.Extension.Equals("src", StringComparison.OrdinalIgnoreCase) || file.Extension.Equals("dat", StringComparison.OrdinalIgnoreCase);

    public TwinCheck Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        TwinVerification<KrlProgramState> result = KrlVerifier.Verify(files, actions, Options(model, limits), cancellation);
        return new TwinCheck(result.Passed, result.ToText);
    }

    public TwinRun Run(IReadOnlyList<(string Name, string Text)> files, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        KrlTwinOptions options = Options(model, limits);
        using var twin = new KrlTwinController(options);
        try
        {
            twin.Load([.. files]);
        }
        catch (KrlLoadException ex)
        {
            return TwinRun.Refused(ex.Message);
        }
        KrlProgramState state = twin.Run(null, cancellation);
        return new TwinRun(null, state == KrlProgramState.Finished, twin.Error, [.. twin.Arm.Trace], twin.Clock.Seconds, options.StartJoints);
    }

    private static KrlTwinOptions Options(RobotModel model, TwinLimits limits) => new() { Model = model, Limits = limits };
}
