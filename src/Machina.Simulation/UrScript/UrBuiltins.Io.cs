using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    private static void AddIo(Dictionary<string, UrBuiltin> t)
    {
        AddDigitalOut(t, "set_standard_digital_out", UrIoBanks.StandardOut);
        AddDigitalOut(t, "set_configurable_digital_out", UrIoBanks.ConfigurableOut);
        AddDigitalOut(t, "set_tool_digital_out", UrIoBanks.ToolOut);
        AddDigitalOut(t, "set_digital_out", UrIoBanks.StandardOut);
        AddDigitalIn(t, "get_standard_digital_in", UrIoBanks.StandardIn);
        AddDigitalIn(t, "get_standard_digital_out", UrIoBanks.StandardOut);
        AddDigitalIn(t, "get_configurable_digital_in", UrIoBanks.ConfigurableIn);
        AddDigitalIn(t, "get_configurable_digital_out", UrIoBanks.ConfigurableOut);
        AddDigitalIn(t, "get_tool_digital_in", UrIoBanks.ToolIn);
        AddDigitalIn(t, "get_tool_digital_out", UrIoBanks.ToolOut);
        Add(t, "set_standard_analog_out", (m, line, a) =>
        {
            int n = Pin(m, line, a, "set_standard_analog_out", UrIoBanks.AnalogOut);
            double value = Num(a, 1, line, "set_standard_analog_out", "f");
            if (!(value >= 0 && value <= 1))
            {
                throw new UrRuntimeException(line, $"set_standard_analog_out: the value {UrValue.FormatNumber(value)} is outside 0 to 1 (the relative output)");
            }
            m.Controller.Io.SetNumber(UrIoBanks.AnalogOut, n, value);
            m.Controller.Arm.Record(line, TwinTraceKind.Output, $"{UrIoBanks.AnalogOut}[{n}] = {UrValue.FormatNumber(value)}");
            return UrNone.Value;
        }, R("n"), R("f"));
        Add(t, "set_analog_out", (m, line, a) => t["set_standard_analog_out"].Invoke(m, line, a), R("n"), R("f"));
        AddNumberIn(t, "get_standard_analog_in", UrIoBanks.AnalogIn);
        AddNumberIn(t, "get_standard_analog_out", UrIoBanks.AnalogOut);
        AddNumberIn(t, "get_tool_analog_in", UrIoBanks.ToolAnalogIn);
        AddDeprecatedIo(t);
        Add(t, "set_flag", (m, line, a) =>
        {
            m.Controller.Io.SetBit(UrIoBanks.Flags, Pin(m, line, a, "set_flag", UrIoBanks.Flags), Bool(a, 1, line, "set_flag", "b"));
            return UrNone.Value;
        }, R("n"), R("b"));
        AddDigitalIn(t, "get_flag", UrIoBanks.Flags);

        Add(t, "read_input_boolean_register", (m, line, a) => UrValue.Box(m.Controller.Io.GetBit(UrIoBanks.InputBoolRegisters,
            Pin(m, line, a, "read_input_boolean_register", UrIoBanks.InputBoolRegisters))), R("address"));
        Add(t, "read_output_boolean_register", (m, line, a) => UrValue.Box(m.Controller.Io.GetBit(UrIoBanks.OutputBoolRegisters,
            Pin(m, line, a, "read_output_boolean_register", UrIoBanks.OutputBoolRegisters))), R("address"));
        Add(t, "read_input_integer_register", (m, line, a) => (int)m.Controller.Io.GetNumber(UrIoBanks.InputIntRegisters,
            Pin(m, line, a, "read_input_integer_register", UrIoBanks.InputIntRegisters)), R("address"));
        Add(t, "read_output_integer_register", (m, line, a) => (int)m.Controller.Io.GetNumber(UrIoBanks.OutputIntRegisters,
            Pin(m, line, a, "read_output_integer_register", UrIoBanks.OutputIntRegisters)), R("address"));
        Add(t, "read_input_float_register", (m, line, a) => m.Controller.Io.GetNumber(UrIoBanks.InputFloatRegisters,
            Pin(m, line, a, "read_input_float_register", UrIoBanks.InputFloatRegisters)), R("address"));
        Add(t, "read_output_float_register", (m, line, a) => m.Controller.Io.GetNumber(UrIoBanks.OutputFloatRegisters,
            Pin(m, line, a, "read_output_float_register", UrIoBanks.OutputFloatRegisters)), R("address"));
        Add(t, "write_output_boolean_register", (m, line, a) =>
        {
            m.Controller.Io.SetBit(UrIoBanks.OutputBoolRegisters, Pin(m, line, a, "write_output_boolean_register", UrIoBanks.OutputBoolRegisters),
                Bool(a, 1, line, "write_output_boolean_register", "value"));
            return UrNone.Value;
        }, R("address"), R("value"));
        Add(t, "write_output_integer_register", (m, line, a) =>
        {
            m.Controller.Io.SetNumber(UrIoBanks.OutputIntRegisters, Pin(m, line, a, "write_output_integer_register", UrIoBanks.OutputIntRegisters),
                Int(a, 1, line, "write_output_integer_register", "value"));
            return UrNone.Value;
        }, R("address"), R("value"));
        Add(t, "write_output_float_register", (m, line, a) =>
        {
            m.Controller.Io.SetNumber(UrIoBanks.OutputFloatRegisters, Pin(m, line, a, "write_output_float_register", UrIoBanks.OutputFloatRegisters),
                Num(a, 1, line, "write_output_float_register", "value"));
            return UrNone.Value;
        }, R("address"), R("value"));
    }

    /// <summary>Argument 0 as a signal number of <paramref name="bank"/>, or a runtime error when there is no such signal.</summary>
    private static int Pin(UrMachine m, int line, object[] a, string function, string bank)
    {
        int n = Int(a, 0, line, function, "n");
        int count = m.Controller.Io.Count(bank);
        return n >= 0 && n < count
            ? n
            : throw new UrRuntimeException(line, string.Create(CultureInfo.InvariantCulture, $"{function}: there is no signal {n} (0 to {count - 1})"));
    }

    private static void AddDigitalOut(Dictionary<string, UrBuiltin> t, string name, string bank) =>
        Add(t, name, (m, line, a) =>
        {
            int n = Pin(m, line, a, name, bank);
            bool value = Bool(a, 1, line, name, "b");
            m.Controller.Io.SetBit(bank, n, value);
            m.Controller.Arm.Record(line, TwinTraceKind.Output, $"{bank}[{n}] = {(value ? "True" : "False")}");
            return UrNone.Value;
        }, R("n"), R("b"));

    private static void AddDigitalIn(Dictionary<string, UrBuiltin> t, string name, string bank) =>
        Add(t, name, (m, line, a) => UrValue.Box(m.Controller.Io.GetBit(bank, Pin(m, line, a, name, bank))), R("n"));

    private static void AddNumberIn(Dictionary<string, UrBuiltin> t, string name, string bank) =>
        Add(t, name, (m, line, a) => m.Controller.Io.GetNumber(bank, Pin(m, line, a, name, bank)), R("n"));
}
