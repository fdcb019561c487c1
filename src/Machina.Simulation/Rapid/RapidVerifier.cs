using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Runs a compiled RAPID program's <c>main</c> on the twin controller and compares, step by step, the poses the arm reached and
/// the outputs it set with the library's own cursor applying the same actions.
/// </summary>
internal static class RapidVerifier
{
    private static readonly TwinVerifier<RapidTwinOptions, RapidTwinController, RapidProgramState> Verifier = new()
    {
        // 0.01 mm and 0.05 deg: targets carry 1 µm, quaternions 4 decimals; signal names are case-insensitive.
        Comparison = new(PositionToleranceMm: 0.01, AngleToleranceDegrees: 0.05, StringComparison.OrdinalIgnoreCase),
        OutputOf = OutputOf,
        Create = options => new RapidTwinController(options),
        Finished = RapidProgramState.Finished,
    };

    /// <summary>Loads <paramref name="modules"/> on a twin with <paramref name="options"/>, runs main and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<RapidProgramState> Verify(IReadOnlyList<(string Name, string Text)> modules, IEnumerable<RobotAction> actions,
        RapidTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new RapidTwinOptions { Limits = TwinLimits.Verify };
        List<RobotAction> all = [.. actions];
        // The signals the program uses are declared in the IO configuration, as the compiled program needs them to load.
        options = options with { Signals = [.. options.Signals, .. SignalsOf(all).Where(s => !options.Signals.Any(o => o.Name.Equals(s.Name, StringComparison.OrdinalIgnoreCase)))] };
        return Verifier.Verify(options, all, twin =>
        {
            try
            {
                twin.Load([.. modules]);
                return (twin.Run("main", cancellation), twin.Error);
            }
            catch (RapidLoadException ex)
            {
                return (RapidProgramState.Failed, ex.Module is null ? ex.Message : $"{ex.Module}: {ex.Message}");
            }
        });
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
