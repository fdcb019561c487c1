using Machina.Cli.Commands;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Cli.Twins;

/// <summary>The RAPID twin: a .pgf, .mod or folder of modules, whose main runs in the motion task.</summary>
internal sealed class RapidTwinProgram : ITwinProgram
{
    public BrandDefinition Brand => AbbBrand.Definition;

    public string Language => "RAPID";

    public string Article => "an";

    public string JointsWord => "joints";

    public string? ProgramNoun => "the RAPID program";

    public Func<CliArgs, RobotModel, System.Net.IPAddress, CliContext, Task<int>>? RunLoaded { get; } =
        (args, model, bind, context) => SimLoad.RunAbbAsync(args.Values("--load"), model, context, new SimLoad.Extras(args.Values("--signal"), args.Value("--eio"),
            bind, args.Value("--rws-port") is null ? null : args.Port("--rws-port", 0, allowZero: true), SimCommand.Home(args, context)));

    public bool IsProgram(string fullPath) => Directory.Exists(fullPath)
        || fullPath.EndsWith(".pgf", StringComparison.OrdinalIgnoreCase) || fullPath.EndsWith(".mod", StringComparison.OrdinalIgnoreCase);

    public IReadOnlyList<string> ProgramFiles(string fullPath) => RapidTwinController.ModuleFiles(fullPath);

    public bool Loads(RobotProgramFile file) => file.Extension.Equals("mod", StringComparison.OrdinalIgnoreCase);

    public TwinCheck Verify(IReadOnlyList<(string Name, string Text)> files, List<RobotAction> actions, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(files, actions, Options(model, limits), cancellation);
        return new TwinCheck(result.Passed, result.ToText);
    }

    public TwinRun Run(IReadOnlyList<(string Name, string Text)> files, RobotModel model, TwinLimits limits, CancellationToken cancellation)
    {
        RapidTwinOptions options = Options(model, limits);
        var twin = new RapidTwinController(options);
        try
        {
            twin.Load([.. files]);
        }
        catch (RapidLoadException ex)
        {
            return TwinRun.Refused($"{ex.Module}: {ex.Message}");
        }
        RapidProgramState state = twin.Run("main", cancellation);
        return new TwinRun(null, state == RapidProgramState.Finished, twin.Error, [.. twin.Arm.Trace], twin.Clock.Seconds, options.StartJoints);
    }

    private static RapidTwinOptions Options(RobotModel model, TwinLimits limits) => new() { Model = model, Limits = limits };
}
