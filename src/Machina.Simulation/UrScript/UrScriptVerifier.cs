using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// Runs a compiled URScript program on the twin controller and compares, step by step, the poses the arm reached and the
/// outputs it set with the library's own cursor applying the same actions.
/// </summary>
internal static class UrScriptVerifier
{
    /// <summary>Largest position difference accepted, in mm (scripts carry 1 µm).</summary>
    public const double PositionToleranceMm = 0.01;

    /// <summary>Largest orientation or joint difference accepted, in degrees.</summary>
    public const double AngleToleranceDegrees = 0.01;

    private static readonly TwinComparison Comparison = new(PositionToleranceMm, AngleToleranceDegrees, StringComparison.Ordinal);

    /// <summary>Runs <paramref name="script"/> on a twin with <paramref name="options"/> and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<UrProgramState> Verify(string script, IEnumerable<RobotAction> actions, UrTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new UrTwinOptions { Limits = TwinLimits.Verify };
        List<TwinExpectation> expected = TwinComparison.Expect(actions, options.Model, OutputOf);
        if (TwinComparison.StartOf(expected, options.Model, options.StartJoints) is { } start)
        {
            options = new UrTwinOptions
            {
                Model = options.Model, StartJoints = start, Time = options.Time, RealTime = options.RealTime,
                RandomSeed = options.RandomSeed, SocketOpenTimeout = options.SocketOpenTimeout, Limits = options.Limits,
            };
        }
        using var twin = new UrTwinController(options);
        UrProgramState state = twin.Run(script, cancellation);
        var result = new TwinVerification<UrProgramState> { State = state, Finished = state == UrProgramState.Finished, Error = twin.Error, Seconds = twin.Clock.Seconds };
        result.Warnings.AddRange(twin.Pendant.Lines.Where(l => l.StartsWith("Warning:", StringComparison.Ordinal)));
        Comparison.Fill(result, expected, twin.Arm.Trace);
        return result;
    }

    /// <summary>The outputs the URScript compiler writes (standard outputs 0-7, tool outputs 0-1, analog 0-1 in 0..1), as the trace shows them.</summary>
    private static string? OutputOf(RobotAction action) => action switch
    {
        ActionIODigital io when io.IsDigit && io.PinNumber < (io.IsToolPin ? 2 : 8) =>
            $"{(io.IsToolPin ? UrIoBanks.ToolOut : UrIoBanks.StandardOut)}[{io.PinNumber}] = {(io.On ? "True" : "False")}",
        ActionIOAnalog io when !io.IsToolPin && io.IsDigit && io.PinNumber < 2 && io.Value is >= 0 and <= 1 =>
            $"{UrIoBanks.AnalogOut}[{io.PinNumber}] = {UrValue.FormatNumber(Math.Round(io.Value, 3))}",
        _ => null,
    };
}
