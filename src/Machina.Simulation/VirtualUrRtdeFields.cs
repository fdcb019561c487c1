using System.Globalization;

namespace Machina.Simulation;

/// <summary>
/// The names and types of the RTDE outputs and inputs the virtual UR serves, from UR's RTDE guide (software 5.x); any other
/// name is NOT_FOUND. Registers are numbered as in the guide: bits 64–127 one by one (0–63 as two words), ints and doubles 0–47.
/// </summary>
internal static class VirtualUrRtdeFields
{
    private static readonly Dictionary<string, string> Outputs = new(StringComparer.Ordinal)
    {
        ["timestamp"] = "DOUBLE",
        ["target_q"] = "VECTOR6D",
        ["target_qd"] = "VECTOR6D",
        ["target_qdd"] = "VECTOR6D",
        ["target_current"] = "VECTOR6D",
        ["target_moment"] = "VECTOR6D",
        ["actual_q"] = "VECTOR6D",
        ["actual_qd"] = "VECTOR6D",
        ["actual_current"] = "VECTOR6D",
        ["actual_current_window"] = "VECTOR6D",
        ["joint_control_output"] = "VECTOR6D",
        ["actual_TCP_pose"] = "VECTOR6D",
        ["actual_TCP_speed"] = "VECTOR6D",
        ["actual_TCP_force"] = "VECTOR6D",
        ["target_TCP_pose"] = "VECTOR6D",
        ["target_TCP_speed"] = "VECTOR6D",
        ["actual_digital_input_bits"] = "UINT64",
        ["joint_temperatures"] = "VECTOR6D",
        ["actual_execution_time"] = "DOUBLE",
        ["robot_mode"] = "INT32",
        ["joint_mode"] = "VECTOR6INT32",
        ["safety_mode"] = "INT32",
        ["safety_status"] = "INT32",
        ["actual_tool_accelerometer"] = "VECTOR3D",
        ["speed_scaling"] = "DOUBLE",
        ["target_speed_fraction"] = "DOUBLE",
        ["actual_momentum"] = "DOUBLE",
        ["actual_main_voltage"] = "DOUBLE",
        ["actual_robot_voltage"] = "DOUBLE",
        ["actual_robot_current"] = "DOUBLE",
        ["actual_joint_voltage"] = "VECTOR6D",
        ["actual_digital_output_bits"] = "UINT64",
        ["runtime_state"] = "UINT32",
        ["elbow_position"] = "VECTOR3D",
        ["elbow_velocity"] = "VECTOR3D",
        ["robot_status_bits"] = "UINT32",
        ["safety_status_bits"] = "UINT32",
        ["analog_io_types"] = "UINT32",
        ["standard_analog_input0"] = "DOUBLE",
        ["standard_analog_input1"] = "DOUBLE",
        ["standard_analog_output0"] = "DOUBLE",
        ["standard_analog_output1"] = "DOUBLE",
        ["io_current"] = "DOUBLE",
        ["euromap67_input_bits"] = "UINT32",
        ["euromap67_output_bits"] = "UINT32",
        ["euromap67_24V_voltage"] = "DOUBLE",
        ["euromap67_24V_current"] = "DOUBLE",
        ["tool_mode"] = "UINT32",
        ["tool_analog_input_types"] = "UINT32",
        ["tool_analog_input0"] = "DOUBLE",
        ["tool_analog_input1"] = "DOUBLE",
        ["tool_output_voltage"] = "INT32",
        ["tool_output_current"] = "DOUBLE",
        ["tool_temperature"] = "DOUBLE",
        ["tcp_force_scalar"] = "DOUBLE",
        ["output_bit_registers0_to_31"] = "UINT32",
        ["output_bit_registers32_to_63"] = "UINT32",
        ["input_bit_registers0_to_31"] = "UINT32",
        ["input_bit_registers32_to_63"] = "UINT32",
        ["tool_output_mode"] = "UINT8",
        ["tool_digital_output0_mode"] = "UINT8",
        ["tool_digital_output1_mode"] = "UINT8",
        ["payload"] = "DOUBLE",
        ["payload_cog"] = "VECTOR3D",
        ["payload_inertia"] = "VECTOR6D",
        ["script_control_line"] = "UINT32",
        ["ft_raw_wrench"] = "VECTOR6D",
        ["joint_position_deviation_ratio"] = "DOUBLE",
        ["collision_detection_ratio"] = "DOUBLE",
        ["time_scale_source"] = "UINT32",
        ["tcp_offset"] = "VECTOR6D",
        // Later software's outputs (UR's client library asks for all of them in its exhaustive recipe):
        ["actual_current_as_torque"] = "VECTOR6D",
        ["actual_TCP_acceleration"] = "VECTOR6D",
        ["target_TCP_acceleration"] = "VECTOR6D",
        ["actual_configurable_digital_input_bits"] = "UINT64",
        ["actual_configurable_digital_output_bits"] = "UINT64",
        ["target_execution_time"] = "DOUBLE",
        ["actual_robot_energy_consumed"] = "DOUBLE",
        ["actual_robot_braking_energy_dissipated"] = "DOUBLE",
        ["encoder0_raw"] = "INT32",
        ["encoder1_raw"] = "INT32",
        ["wrench_calc_from_currents"] = "VECTOR6D",
        ["target_gravity"] = "VECTOR3D",
        ["target_base_acceleration"] = "VECTOR6D",
        ["control_step"] = "UINT64",
        ["target_base_wrench"] = "VECTOR6D",
    };

    private static readonly Dictionary<string, string> Inputs = new(StringComparer.Ordinal)
    {
        ["speed_slider_mask"] = "UINT32",
        ["speed_slider_fraction"] = "DOUBLE",
        ["standard_digital_output_mask"] = "UINT8",
        ["standard_digital_output"] = "UINT8",
        ["configurable_digital_output_mask"] = "UINT8",
        ["configurable_digital_output"] = "UINT8",
        ["tool_digital_output_mask"] = "UINT8",
        ["tool_digital_output"] = "UINT8",
        ["standard_analog_output_mask"] = "UINT8",
        ["standard_analog_output_type"] = "UINT8",
        ["standard_analog_output_0"] = "DOUBLE",
        ["standard_analog_output_1"] = "DOUBLE",
        ["input_bit_registers0_to_31"] = "UINT32",
        ["input_bit_registers32_to_63"] = "UINT32",
        ["external_force_torque"] = "VECTOR6D",
    };

    /// <summary>The type of an output name, or NOT_FOUND.</summary>
    public static string OutputType(string name) =>
        Outputs.TryGetValue(name, out string? type) ? type
        : Register(name, "output_") ?? Register(name, "input_") ?? VirtualUrRtdePackages.NotFound;

    /// <summary>The type of an input name, or NOT_FOUND.</summary>
    public static string InputType(string name) =>
        Inputs.TryGetValue(name, out string? type) ? type : Register(name, "input_") ?? VirtualUrRtdePackages.NotFound;

    /// <summary>
    /// The type of a register name with the prefix ("output_" or "input_"): <c>bit_register_64</c>–<c>127</c> BOOL,
    /// <c>int_register_0</c>–<c>47</c> INT32, <c>double_register_0</c>–<c>47</c> DOUBLE; null for another name.
    /// </summary>
    public static string? Register(string name, string prefix) =>
        RegisterNumber(name, prefix + "bit_register_") is >= 64 and <= 127 ? "BOOL"
        : RegisterNumber(name, prefix + "int_register_") is >= 0 and <= 47 ? "INT32"
        : RegisterNumber(name, prefix + "double_register_") is >= 0 and <= 47 ? "DOUBLE"
        : null;

    /// <summary>The number after <paramref name="prefix"/>, or -1.</summary>
    public static int RegisterNumber(string name, string prefix) =>
        name.StartsWith(prefix, StringComparison.Ordinal) && name.Length > prefix.Length && name.Length <= prefix.Length + 3
            && int.TryParse(name.AsSpan(prefix.Length), NumberStyles.None, CultureInfo.InvariantCulture, out int n)
            ? n : -1;

    /// <summary>The names of a recipe: comma-separated, a trailing comma (as some clients send) adding no name.</summary>
    public static string[] Recipe(string text)
    {
        string[] names = text.Split(',');
        return names.Length > 1 && names[^1].Length == 0 ? names[..^1] : names;
    }
}
