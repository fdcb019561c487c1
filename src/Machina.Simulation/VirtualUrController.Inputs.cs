using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// Sets standard digital input <paramref name="pin"/> (0–7), or tool digital input 0–1 when <paramref name="toolPin"/>, as a
    /// sensor wired to it would; the driver script's get_standard_digital_in / get_tool_digital_in see it.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The controller has no such input.</exception>
    public void SetDigitalInput(int pin, bool on, bool toolPin = false)
    {
        string bank = toolPin ? UrIoBanks.ToolIn : UrIoBanks.StandardIn;
        int count = Twin.Io.Count(bank);
        if (pin < 0 || pin >= count)
        {
            throw new ArgumentOutOfRangeException(nameof(pin), pin, $"The virtual UR has {(toolPin ? "tool" : "standard")} digital inputs 0 to {count - 1}.");
        }
        Twin.Io.SetBit(bank, pin, on);
    }

    /// <summary>
    /// Sets standard analog input <paramref name="pin"/> (0–1), or tool analog input 0–1 when <paramref name="toolPin"/>, to a value
    /// (volts or amperes, as the input is configured); the driver script's get_standard_analog_in / get_tool_analog_in see it.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The controller has no such input, or the value is not a finite number.</exception>
    public void SetAnalogInput(int pin, double value, bool toolPin = false)
    {
        string bank = toolPin ? UrIoBanks.ToolAnalogIn : UrIoBanks.AnalogIn;
        int count = Twin.Io.Count(bank);
        if (pin < 0 || pin >= count)
        {
            throw new ArgumentOutOfRangeException(nameof(pin), pin, $"The virtual UR has {(toolPin ? "tool" : "standard")} analog inputs 0 to {count - 1}.");
        }
        if (!double.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, "An analog input holds a finite number.");
        }
        Twin.Io.SetNumber(bank, pin, value);
    }
}
