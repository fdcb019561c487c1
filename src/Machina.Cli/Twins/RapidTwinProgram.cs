using Machina.Cli.Commands;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>The RAPID twin: a .pgf, .mod or folder of modules, whose main runs in the motion task.</summary>
internal sealed class RapidTwinProgram()
    : TwinProgram<RapidTwinOptions, RapidTwinController, RapidProgramState>(AbbBrand.Definition, "RAPID", "an", "joints", "the RAPID program", RapidProgramState.Finished, "mod")
{
    public override Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded { get; } =
        (args, model, bind, context) => SimLoad.RunAbbAsync(args.Values("--load"), model, context, new SimLoad.Extras(args.Values("--signal"), args.Value("--eio"),
            bind, args.Value("--rws-port") is null ? null : args.Port("--rws-port", 0, allowZero: true), SimCommand.Home(args, context))
        {
            TaskTypes = args.Values("--task-type"),
            Cycle = args.Value("--cycle"),
        });

    public override IReadOnlyList<string> LoadOptions { get; } = ["--bind", "--rws-port", "--home", "--signal", "--eio", "--task-type", "--cycle"];

    public override bool LoadsSeveral => true;

    public override bool IsProgram(string fullPath) => Directory.Exists(fullPath)
        || fullPath.EndsWith(".pgf", StringComparison.OrdinalIgnoreCase) || fullPath.EndsWith(".mod", StringComparison.OrdinalIgnoreCase);

    public override IReadOnlyList<string> ProgramFiles(string fullPath) => RapidTwinController.ModuleFiles(fullPath);

    protected override TwinVerification<RapidProgramState> Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, RapidTwinOptions options, CancellationToken cancellation) =>
        RapidVerifier.Verify(files, actions, options, cancellation);

    protected override RapidTwinController Create(RapidTwinOptions options) => new(options);

    protected override void Load(RapidTwinController twin, IReadOnlyList<(string Name, string Text)> files) => twin.Load([.. files]);

    protected override string? Refusal(Exception e) => e is RapidLoadException ex ? $"{ex.Module}: {ex.Message}" : null;

    protected override RapidProgramState RunMain(RapidTwinController twin, IReadOnlyList<(string Name, string Text)> files, CancellationToken cancellation) =>
        twin.Run("main", cancellation);
}
