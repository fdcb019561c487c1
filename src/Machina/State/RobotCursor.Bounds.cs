namespace Machina;

internal sealed partial class RobotCursor
{
    /// <summary>
    /// The largest value a setting may reach, in its own unit (mm/s, mm/s^2, mm, mm/mm, degrees C, an analog output's value):
    /// no robot or printer uses more, and every language Machina writes (RAPID's and KRL's 32-bit numbers, URScript, G-code)
    /// holds it. Beyond it a program would be written with numbers its controller cannot read.
    /// </summary>
    internal const double MaxSetting = 1_000_000;

    /// <summary>The longest wait, ms: 1,000,000 s (about 11.6 days); every language's timer holds it.</summary>
    internal const long MaxWaitMillis = 1_000_000_000;

    /// <summary>Why <paramref name="value"/> is beyond <see cref="MaxSetting"/> (or not a number), or null when it is within.</summary>
    private static string? BeyondSettingLimit(string what, double value, string unit) =>
        Math.Abs(value) <= MaxSetting
            ? null
            : $"the {what} would become {Num.G(value)} {unit}; settings are refused beyond 1,000,000 {unit}, which no robot or printer uses and not every robot language can hold.";

    private static string? CheckWait(ActionWait a) =>
        a.Millis <= MaxWaitMillis
            ? null
            : $"a wait of {Num.I(a.Millis)} ms is refused: waits are limited to 1,000,000,000 ms (1,000,000 s, about 11.6 days), the longest every robot language's timer holds.";

    private static string? CheckWaitDigital(ActionWaitDigital a) =>
        a.TimeoutMillis <= MaxWaitMillis
            ? null
            : $"a wait for input {a.PinName} of at most {Num.I(a.TimeoutMillis)} ms is refused: waits are limited to 1,000,000,000 ms (1,000,000 s, about 11.6 days), the longest every robot language's timer holds.";

    private static string? CheckAnalog(ActionIOAnalog a) =>
        Math.Abs(a.Value) <= MaxSetting
            ? null
            : $"the analog output {a.PinName} would be set to {Num.G(a.Value)}; analog values are refused beyond ±1,000,000, which no output takes and not every robot language can hold.";

    /// <summary>A tool whose tip or centre of gravity is beyond 1 km, or which weighs more than 1,000,000 kg, is refused.</summary>
    private static string? CheckTool(ActionDefineTool a)
    {
        Tool tool = a.Tool;
        if (!WithinReach(tool.TcpPosition) || !WithinReach(tool.CenterOfGravity))
        {
            return $"tool \"{tool.Name}\" has its tip at {tool.TcpPosition} mm and its centre of gravity at {tool.CenterOfGravity} mm; tool coordinates are refused beyond 1,000,000 mm (1 km), which no tool reaches.";
        }
        if (tool.Weight > MaxSetting)
        {
            return $"tool \"{tool.Name}\" would weigh {Num.G(tool.Weight)} kg; tool weights are refused beyond 1,000,000 kg, which no robot carries and not every robot language can hold.";
        }
        return null;
    }
}
