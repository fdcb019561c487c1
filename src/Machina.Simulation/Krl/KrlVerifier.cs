using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// Runs a compiled KRL program (its <c>.src</c> and <c>.dat</c>) on the KRL twin and compares, step by step, the poses the arm
/// reached and the outputs it set with the library's own cursor applying the same actions. The BCO run (the first motion, to
/// where the robot already is) is not one of the program's steps.
/// </summary>
internal static class KrlVerifier
{
    /// <summary>Largest position difference accepted, in mm (KRL targets carry 3 decimals).</summary>
    public const double PositionToleranceMm = 0.01;

    /// <summary>Largest orientation or joint difference accepted, in degrees (A, B, C carry 3 decimals).</summary>
    public const double AngleToleranceDegrees = 0.05;

    private static readonly TwinComparison Comparison = new(PositionToleranceMm, AngleToleranceDegrees, StringComparison.OrdinalIgnoreCase);

    /// <summary>Loads <paramref name="files"/> on a twin with <paramref name="options"/>, runs the main routine and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<KrlProgramState> Verify(IReadOnlyList<(string Name, string Text)> files, IEnumerable<RobotAction> actions,
        KrlTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new KrlTwinOptions { Limits = TwinLimits.Verify };
        List<RobotAction> all = [.. actions];
        List<TwinExpectation> expected = TwinComparison.Expect(all, options.Model, OutputOf);
        List<string> named = [.. all.OfType<ActionIODigital>().Where(d => !d.IsDigit).Select(d => d.PinName)
            .Where(n => !options.Signals.Any(s => s.Name.Equals(n, StringComparison.OrdinalIgnoreCase))).Distinct(StringComparer.OrdinalIgnoreCase)];
        options = new KrlTwinOptions
        {
            Model = options.Model, StartJoints = TwinComparison.StartOf(expected, options.Model, options.StartJoints) ?? options.StartJoints, Time = options.Time,
            RealTime = options.RealTime, DefaultCpVelocity = options.DefaultCpVelocity, DefaultCpAcceleration = options.DefaultCpAcceleration,
            DefaultAxisSpeed = options.DefaultAxisSpeed, AxisRampSeconds = options.AxisRampSeconds, Limits = options.Limits,
            // Named outputs are SIGNALs of $CONFIG.DAT on a real controller: the twin maps each to one of the last outputs.
            Signals = [.. options.Signals, .. named.Select((n, i) => (n, KrlSystemVariables.DigitalCount - i))],
        };
        using var twin = new KrlTwinController(options);
        KrlProgramState state;
        string? error;
        try
        {
            twin.Load([.. files]);
            state = twin.Run(null, cancellation);
            error = twin.Error;
        }
        catch (KrlLoadException ex)
        {
            state = KrlProgramState.Failed;
            error = ex.Message;
        }
        var result = new TwinVerification<KrlProgramState> { State = state, Finished = state == KrlProgramState.Finished, Error = error, Seconds = twin.Clock.Seconds };
        Comparison.Fill(result, expected, twin.Arm.Trace.Where(e => !e.Text.EndsWith(KrlTwinController.BcoRun, StringComparison.Ordinal)));
        return result;
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
