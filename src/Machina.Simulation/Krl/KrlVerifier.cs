using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// Runs a compiled KRL program (its <c>.src</c> and <c>.dat</c>) on the KRL twin and compares, step by step, the poses the arm
/// reached and the outputs it set with the library's own cursor applying the same actions. The BCO run (the first motion, to
/// where the robot already is) is not one of the program's steps.
/// </summary>
internal static class KrlVerifier
{
    private static readonly TwinVerifier<KrlTwinOptions, KrlTwinController, KrlProgramState> Verifier = new()
    {
        // 0.01 mm and 0.05 deg: KRL targets and A, B, C carry 3 decimals; signal names are case-insensitive.
        Comparison = new(PositionToleranceMm: 0.01, AngleToleranceDegrees: 0.05, StringComparison.OrdinalIgnoreCase),
        OutputOf = OutputOf,
        Create = options => new KrlTwinController(options),
        Finished = KrlProgramState.Finished,
        IsStep = e => !e.Text.EndsWith(KrlTwinController.BcoRun, StringComparison.Ordinal),
    };

    /// <summary>Loads <paramref name="files"/> on a twin with <paramref name="options"/>, runs the main routine and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<KrlProgramState> Verify(IReadOnlyList<(string Name, string Text)> files, IEnumerable<RobotAction> actions,
        KrlTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new KrlTwinOptions { Limits = TwinLimits.Verify };
        List<RobotAction> all = [.. actions];
        List<string> named = [.. all.OfType<ActionIODigital>().Where(d => !d.IsDigit).Select(d => d.PinName)
            .Where(n => !options.Signals.Any(s => s.Name.Equals(n, StringComparison.OrdinalIgnoreCase))).Distinct(StringComparer.OrdinalIgnoreCase)];
        // Named outputs are SIGNALs of $CONFIG.DAT on a real controller: the twin maps each to one of the last outputs.
        options = options with { Signals = [.. options.Signals, .. named.Select((n, i) => (n, KrlSystemVariables.DigitalCount - i))] };
        return Verifier.Verify(options, all, twin =>
        {
            try
            {
                twin.Load([.. files]);
                return (twin.Run(null, cancellation), twin.Error);
            }
            catch (KrlLoadException ex)
            {
                return (KrlProgramState.Failed, ex.Message);
            }
        });
    }

    /// <summary>The outputs the KRL compiler writes, as the twin's trace shows them.</summary>
    private static string? OutputOf(RobotAction action) => action switch
    {
        ActionIODigital io when io.IsDigit => $"$OUT[{io.PinNumber}] = {(io.On ? "TRUE" : "FALSE")}",
        ActionIODigital io => $"{io.PinName} = {(io.On ? "TRUE" : "FALSE")}",
        ActionIOAnalog io when io.IsDigit => $"$ANOUT[{io.PinNumber}] = {KrlValues.Format(Math.Round(io.Value, 6))}",
        _ => null,
    };
}
