using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// Runs a compiled URScript program on the twin controller and compares, step by step, the poses the arm reached and the
/// outputs it set with the library's own cursor applying the same actions.
/// </summary>
internal static class UrScriptVerifier
{
    private static readonly TwinVerifier<UrTwinOptions, UrTwinController, UrProgramState> Verifier = new()
    {
        // 0.01 mm and 0.01 deg: scripts carry 1 µm.
        Comparison = new(PositionToleranceMm: 0.01, AngleToleranceDegrees: 0.01, StringComparison.Ordinal),
        OutputOf = OutputOf,
        Create = options => new UrTwinController(options),
        Finished = UrProgramState.Finished,
        Warnings = twin => twin.Pendant.Lines.Where(l => l.StartsWith("Warning:", StringComparison.Ordinal)),
    };

    /// <summary>Runs <paramref name="script"/> on a twin with <paramref name="options"/> and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<UrProgramState> Verify(string script, IEnumerable<RobotAction> actions, UrTwinOptions? options = null, CancellationToken cancellation = default) =>
        Verifier.Verify(options ?? new UrTwinOptions { Limits = TwinLimits.Verify }, actions, twin => (twin.Run(script, cancellation), twin.Error));

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
