using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Cli.Twins;

/// <summary>The URScript twin: a <c>.script</c> file, run as the robot runs a program sent to it.</summary>
internal sealed class UrScriptTwinProgram : ITwinProgram
{
    public BrandDefinition Brand => UrBrand.Definition;

    public string Language => "URScript";

    public string Article => "a";

    public string JointsWord => "joints";

    public string? ProgramNoun => null;

    public Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded => null;

    public bool IsProgram(string fullPath) => fullPath.EndsWith(".script", StringComparison.OrdinalIgnoreCase);

    public IReadOnlyList<string> ProgramFiles(string fullPath) => [fullPath];

    public bool Loads(RobotProgramFile file) => file.Extension.Equals("script", StringComparison.OrdinalIgnoreCase);

    public TwinCheck Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify(files[0].Text, actions, Options(model, limits), cancellation);
        return new TwinCheck(result.Passed, result.ToText);
    }

    public TwinRun Run(IReadOnlyList<(string Name, string Text)> files, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        UrTwinOptions options = Options(model, limits);
        using var twin = new UrTwinController(options);
        UrProgramState state = twin.Run(files[0].Text, cancellation);
        return new TwinRun(null, state == UrProgramState.Finished, twin.Error, [.. twin.Arm.Trace], twin.Clock.Seconds, options.StartJoints);
    }

    private static UrTwinOptions Options(RobotModel model, TwinLimits limits) => new() { Model = model, Limits = limits };
}
