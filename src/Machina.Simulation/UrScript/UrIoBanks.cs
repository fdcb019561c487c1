namespace Machina.Simulation.UrScript;

/// <summary>Names of the UR controller's signal banks in <see cref="Twin.TwinIo"/>.</summary>
internal static class UrIoBanks
{
    /// <summary>Standard digital inputs 0–7.</summary>
    public const string StandardIn = "standard_digital_in";

    /// <summary>Standard digital outputs 0–7.</summary>
    public const string StandardOut = "standard_digital_out";

    /// <summary>Configurable digital inputs 0–7.</summary>
    public const string ConfigurableIn = "configurable_digital_in";

    /// <summary>Configurable digital outputs 0–7.</summary>
    public const string ConfigurableOut = "configurable_digital_out";

    /// <summary>Tool digital inputs 0–1.</summary>
    public const string ToolIn = "tool_digital_in";

    /// <summary>Tool digital outputs 0–1.</summary>
    public const string ToolOut = "tool_digital_out";

    /// <summary>Standard analog inputs 0–1.</summary>
    public const string AnalogIn = "standard_analog_in";

    /// <summary>Standard analog outputs 0–1.</summary>
    public const string AnalogOut = "standard_analog_out";

    /// <summary>Tool analog inputs 0–1.</summary>
    public const string ToolAnalogIn = "tool_analog_in";

    /// <summary>Flags 0–32 (<c>set_flag</c>, <c>get_flag</c>): internal bits that keep their values between program runs.</summary>
    public const string Flags = "flag";

    /// <summary>RTDE input boolean registers 0–127.</summary>
    public const string InputBoolRegisters = "input_boolean_register";

    /// <summary>RTDE output boolean registers 0–127.</summary>
    public const string OutputBoolRegisters = "output_boolean_register";

    /// <summary>RTDE input integer registers 0–47.</summary>
    public const string InputIntRegisters = "input_integer_register";

    /// <summary>RTDE output integer registers 0–47.</summary>
    public const string OutputIntRegisters = "output_integer_register";

    /// <summary>RTDE input float registers 0–47.</summary>
    public const string InputFloatRegisters = "input_float_register";

    /// <summary>RTDE output float registers 0–47.</summary>
    public const string OutputFloatRegisters = "output_float_register";
}
