using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Runs a compiled RAPID program's <c>main</c> on the twin controller and compares, step by step, the poses the arm reached and
/// the outputs it set with the library's own cursor applying the same actions.
/// </summary>
internal static class RapidVerifier
{
    /// <summary>Largest position difference accepted, in mm (targets carry 1 µm).</summary>
    public const double PositionToleranceMm = 0.01;

    /// <summary>Largest orientation or joint difference accepted, in degrees (quaternions are written with 4 decimals).</summary>
    public const double AngleToleranceDegrees = 0.05;

    private static readonly TwinComparison Comparison = new(PositionToleranceMm, AngleToleranceDegrees, StringComparison.OrdinalIgnoreCase);

    /// <summary>Loads <paramref name="modules"/> on a twin with <paramref name="options"/>, runs main and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<RapidProgramState> Verify(IReadOnlyList<(string Name, string Text)> modules, IEnumerable<RobotAction> actions,
        RapidTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new RapidTwinOptions { Limits = TwinLimits.Verify };
        List<RobotAction> all = [.. actions];
        List<TwinExpectation> expected = TwinComparison.Expect(all, options.Model, OutputOf);
        options = new RapidTwinOptions
        {
            Model = options.Model, StartJoints = TwinComparison.StartOf(expected, options.Model, options.StartJoints) ?? options.StartJoints, Time = options.Time,
            RealTime = options.RealTime, Acceleration = options.Acceleration, Limits = options.Limits,
            Signals = [.. options.Signals, .. SignalsOf(all).Where(s => !options.Signals.Any(o => o.Name.Equals(s.Name, StringComparison.OrdinalIgnoreCase)))],
        };
        var twin = new RapidTwinController(options);
        RapidProgramState state;
        string? error;
        try
        {
            twin.Load([.. modules]);
            state = twin.Run("main", cancellation);
            error = twin.Error;
        }
        catch (RapidLoadException ex)
        {
            state = RapidProgramState.Failed;
            error = ex.Module is null ? ex.Message : $"{ex.Module}: {ex.Message}";
        }
        var result = new TwinVerification<RapidProgramState> { State = state, Finished = state == RapidProgramState.Finished, Error = error, Seconds = twin.Clock.Seconds };
        Comparison.Fill(result, expected, twin.Arm.Trace);
        return result;
    }

    /// <summary>The outputs the RAPID compiler writes (named signals only), as the trace shows them.</summary>
    private static string? OutputOf(RobotAction action) => action switch
    {
        ActionIODigital io when !io.IsDigit => $"{io.PinName} = {(io.On ? 1 : 0)}",
        ActionIOAnalog io when !io.IsDigit => $"{io.PinName} = {RapidValues.FormatNumber(Math.Round(io.Value, 6))}",
        _ => null,
    };

    /// <summary>
    /// The named signals the actions set, wait for or read, as the controller's IO configuration must declare them for the compiled
    /// program to load: outputs, and the inputs of WaitForDigital, ReadDigital and ReadAnalog (issue 46; numbered pins do not exist
    /// on an ABB controller and are not compiled). The inputs read 0 on the twin until something sets them.
    /// </summary>
    internal static IEnumerable<(string Name, string Type)> SignalsOf(IEnumerable<RobotAction> actions) => actions
        .Select(a => a switch
        {
            ActionIODigital d when !d.IsDigit => (d.PinName, "signaldo"),
            ActionIOAnalog an when !an.IsDigit => (an.PinName, "signalao"),
            ActionWaitDigital w when !w.IsDigit => (w.PinName, "signaldi"),
            ActionReadInput r when !r.IsDigit => (r.PinName, r.IsAnalog ? "signalai" : "signaldi"),
            _ => ((string, string)?)null,
        })
        .OfType<(string, string)>()
        .DistinctBy(s => s.Item1, StringComparer.OrdinalIgnoreCase);
}
