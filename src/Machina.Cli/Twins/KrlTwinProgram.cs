using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>The KRL twin: a .src file (with its .dat) or a folder, whose main routine runs.</summary>
internal sealed class KrlTwinProgram()
    : TwinProgram<KrlTwinOptions, KrlTwinController, KrlProgramState>(KukaBrand.Definition, "KRL", "a", "axes", "the KRL program", KrlProgramState.Finished, "src", "dat")
{
    public override Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded { get; } =
        (args, model, _, context) => KrlSimRun.RunAsync(args.Value("--load")!, args.Value("--select"), model, context);

    public override IReadOnlyList<string> LoadOptions { get; } = ["--select"];

    public override bool IsProgram(string fullPath) => fullPath.EndsWith(".src", StringComparison.OrdinalIgnoreCase)
        || (Directory.Exists(fullPath) && Directory.GetFiles(fullPath, "*.src").Length > 0);

    public override IReadOnlyList<string> ProgramFiles(string fullPath) => KrlTwinController.ProgramFiles(fullPath);

    protected override TwinVerification<KrlProgramState> Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, KrlTwinOptions options, CancellationToken cancellation) =>
        KrlVerifier.Verify(files, actions, options, cancellation);

    protected override KrlTwinController Create(KrlTwinOptions options) => new(options);

    protected override void Load(KrlTwinController twin, IReadOnlyList<(string Name, string Text)> files) => twin.Load([.. files]);

    protected override string? Refusal(Exception e) => e is KrlLoadException ex ? ex.Message : null;

    protected override KrlProgramState RunMain(KrlTwinController twin, IReadOnlyList<(string Name, string Text)> files, CancellationToken cancellation) =>
        twin.Run(null, cancellation);
}
