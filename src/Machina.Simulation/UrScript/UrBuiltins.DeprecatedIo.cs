using System.Globalization;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>
    /// The deprecated I/O getters of the older controllers (CB2 programs such as the ROS <c>ur_driver</c>'s call them): their
    /// numbers run on past the standard signals into the tool's (the Script Manual's note: ports 8-9 of <c>get_digital_in</c> are
    /// <c>get_tool_digital_in</c>'s 0-1), so <c>get_digital_in</c>/<c>get_digital_out</c> take 0-9 and <c>get_analog_in</c> 0-3;
    /// <c>get_analog_out</c> reads the standard analog outputs 0-1.
    /// </summary>
    private static void AddDeprecatedIo(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "get_digital_in", (m, line, a) =>
        {
            (string bank, int n) = SignalOrTool(m, line, a, "get_digital_in", UrIoBanks.StandardIn, UrIoBanks.ToolIn);
            return UrValue.Box(m.Controller.Io.GetBit(bank, n));
        }, R("n"));
        Add(t, "get_digital_out", (m, line, a) =>
        {
            (string bank, int n) = SignalOrTool(m, line, a, "get_digital_out", UrIoBanks.StandardOut, UrIoBanks.ToolOut);
            return UrValue.Box(m.Controller.Io.GetBit(bank, n));
        }, R("n"));
        Add(t, "get_analog_in", (m, line, a) =>
        {
            (string bank, int n) = SignalOrTool(m, line, a, "get_analog_in", UrIoBanks.AnalogIn, UrIoBanks.ToolAnalogIn);
            return m.Controller.Io.GetNumber(bank, n);
        }, R("n"));
        AddNumberIn(t, "get_analog_out", UrIoBanks.AnalogOut);
    }

    /// <summary>
    /// Signal <c>n</c> of <paramref name="standard"/>, or past its last one the tool's (<paramref name="tool"/>, from 0). Another
    /// number stops the program with the line, as the other signal functions do.
    /// </summary>
    private static (string Bank, int N) SignalOrTool(UrMachine m, int line, object[] a, string function, string standard, string tool)
    {
        int n = Int(a, 0, line, function, "n");
        int count = m.Controller.Io.Count(standard), toolCount = m.Controller.Io.Count(tool);
        if (n >= 0 && n < count)
        {
            return (standard, n);
        }
        if (n >= count && n < count + toolCount)
        {
            return (tool, n - count);
        }
        throw new UrRuntimeException(line, string.Create(CultureInfo.InvariantCulture, $"{function}: there is no signal {n} (0 to {count + toolCount - 1})"));
    }
}
