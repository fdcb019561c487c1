using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Cli.Twins;

/// <summary>The URScript twin: a <c>.script</c> file, run as the robot runs a program sent to it.</summary>
internal sealed class UrScriptTwinProgram()
    : TwinProgram<UrTwinOptions, UrTwinController, UrProgramState>(UrBrand.Definition, "URScript", "a", "joints", null, UrProgramState.Finished, "script")
{
    public override Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded => null;

    public override bool IsProgram(string fullPath) => fullPath.EndsWith(".script", StringComparison.OrdinalIgnoreCase);

    public override IReadOnlyList<string> ProgramFiles(string fullPath) => [fullPath];

    protected override TwinVerification<UrProgramState> Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, UrTwinOptions options, CancellationToken cancellation) =>
        UrScriptVerifier.Verify(files[0].Text, actions, options, cancellation);

    protected override UrTwinController Create(UrTwinOptions options) => new(options);

    protected override void Load(UrTwinController twin, IReadOnlyList<(string Name, string Text)> files)
    {
        // a script is sent and run at once: nothing to load before
    }

    protected override string? Refusal(Exception e) => null;

    protected override UrProgramState RunMain(UrTwinController twin, IReadOnlyList<(string Name, string Text)> files, CancellationToken cancellation) =>
        twin.Run(files[0].Text, cancellation);
}
