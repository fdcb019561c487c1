using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// The outputs of one RTDE data package from the interpreter (RTDE guide: each output big-endian in SI units): the arm's
    /// joints and tool centre point, the program's runtime state, modes and status bits, I/O and registers. What the twin does
    /// not model (currents, temperatures, forces, accelerations) reads as a standing arm's: zero, or nominal values. The
    /// controller's state is taken once per tick, and only when a recipe asks for more than the time and registers.
    /// </summary>
    private static void WriteOutputs(UrTwinController twin, VirtualUrRtdeWriter payload, string[] names, RtdeSnapshot snapshot)
    {
        foreach (string name in names)
        {
            if (name == "timestamp")
            {
                payload.Double(snapshot.Time); // controller time, as a UR reports it
                continue;
            }
            if (IsRegister(name))
            {
                WriteRegister(twin, payload, name);
                continue;
            }
            VirtualUrClientState s = snapshot.State;
            switch (name)
            {
                case "actual_q" or "target_q":
                    payload.Doubles(s.Q);
                    break;
                case "actual_qd" or "target_qd":
                    payload.Doubles(s.Qd);
                    break;
                case "actual_TCP_pose" or "target_TCP_pose":
                    payload.Doubles(s.Tcp);
                    break;
                case "actual_TCP_speed" or "target_TCP_speed":
                    payload.Doubles(s.TcpSpeed);
                    break;
                case "tcp_offset":
                    payload.Doubles(s.TcpOffset);
                    break;
                case "robot_mode":
                    payload.Int32(s.RobotMode);
                    break;
                case "joint_mode":
                    for (int i = 0; i < 6; i++)
                    {
                        payload.Int32(s.RobotMode == RunningMode ? 253 : s.PowerOn ? 255 : 239);
                    }
                    break;
                case "safety_mode" or "safety_status":
                    payload.Int32(s.SafetyMode);
                    break;
                case "runtime_state":
                    payload.UInt32(s.RuntimeState);
                    break;
                case "speed_scaling" or "target_speed_fraction":
                    payload.Double(s.SpeedFraction);
                    break;
                case "actual_digital_output_bits":
                    payload.UInt64(s.DigitalOutputs);
                    break;
                case "actual_digital_input_bits":
                    payload.UInt64(s.DigitalInputs);
                    break;
                case "actual_configurable_digital_output_bits": // configurable 0–7 in bits 0–7
                    payload.UInt64((s.DigitalOutputs >> 8) & 0xFF);
                    break;
                case "actual_configurable_digital_input_bits":
                    payload.UInt64((s.DigitalInputs >> 8) & 0xFF);
                    break;
                case "robot_status_bits": // power on, program running, teach button, power button
                    payload.Int32((s.PowerOn ? 1 : 0) | (s.ProgramRunning && !s.ProgramPaused ? 2 : 0));
                    break;
                case "safety_status_bits": // normal, reduced, protective stopped, …, robot emergency stopped (bit 6)
                    payload.Int32(s.SafetyMode switch { ProtectiveStopped => 1 << 2, RobotEmergencyStopped => 1 << 6, _ => 1 });
                    break;
                case "standard_analog_input0" or "standard_analog_input1":
                    payload.Double(s.AnalogIn[name[^1] - '0']);
                    break;
                case "standard_analog_output0" or "standard_analog_output1":
                    payload.Double(s.AnalogOut[name[^1] - '0']);
                    break;
                case "tool_analog_input0" or "tool_analog_input1":
                    payload.Double(s.ToolAnalogIn[name[^1] - '0']);
                    break;
                case "actual_main_voltage" or "actual_robot_voltage":
                    payload.Double(s.PowerOn ? 48 : 0);
                    break;
                case "actual_joint_voltage":
                    payload.Doubles(s.PowerOn ? [48, 48, 48, 48, 48, 48] : [0, 0, 0, 0, 0, 0]);
                    break;
                case "joint_temperatures":
                    payload.Doubles([30, 30, 30, 30, 30, 30]);
                    break;
                case "tool_temperature":
                    payload.Double(30);
                    break;
                case "actual_tool_accelerometer":
                    payload.Doubles([0, 0, -9.82]); // a tool pointing down at rest
                    break;
                case "payload":
                    payload.Double(s.Payload);
                    break;
                case "actual_execution_time" or "target_execution_time":
                    payload.Double(0.002);
                    break;
                case "target_gravity": // set_gravity's vector, or the controller's default
                    payload.Doubles(twin.Modes.Gravity);
                    break;
                case "control_step": // the 2 ms control steps since the controller started
                    payload.UInt64((ulong)Math.Round(snapshot.Time * 500));
                    break;
                default: // an output the twin does not model: zeros of its type
                    payload.Zeros(VirtualUrRtdePackages.SizeOf(VirtualUrRtdeFields.OutputType(name)));
                    break;
            }
        }
    }

    /// <summary>True for a register output: one register, or 32 bit registers as one word.</summary>
    private static bool IsRegister(string name) =>
        name is "output_bit_registers0_to_31" or "output_bit_registers32_to_63" or "input_bit_registers0_to_31" or "input_bit_registers32_to_63"
        || VirtualUrRtdeFields.Register(name, "output_") is not null || VirtualUrRtdeFields.Register(name, "input_") is not null;

    /// <summary>A register output, as the running program and the RTDE inputs left it.</summary>
    private static void WriteRegister(UrTwinController twin, VirtualUrRtdeWriter payload, string name)
    {
        if (name is "output_bit_registers0_to_31" or "output_bit_registers32_to_63" or "input_bit_registers0_to_31" or "input_bit_registers32_to_63")
        {
            string bank = name.StartsWith("output", StringComparison.Ordinal) ? UrIoBanks.OutputBoolRegisters : UrIoBanks.InputBoolRegisters;
            payload.UInt32(RegisterWord(twin, bank, name.Contains("32_to", StringComparison.Ordinal) ? 32 : 0));
            return;
        }
        string prefix = name.StartsWith("output_", StringComparison.Ordinal) ? "output_" : "input_";
        bool output = prefix == "output_";
        if (VirtualUrRtdeFields.RegisterNumber(name, prefix + "bit_register_") is int bit and >= 64)
        {
            payload.Byte(twin.Io.GetBit(output ? UrIoBanks.OutputBoolRegisters : UrIoBanks.InputBoolRegisters, bit) ? (byte)1 : (byte)0);
        }
        else if (VirtualUrRtdeFields.RegisterNumber(name, prefix + "int_register_") is int integer and >= 0)
        {
            payload.Int32((int)twin.Io.GetNumber(output ? UrIoBanks.OutputIntRegisters : UrIoBanks.InputIntRegisters, integer));
        }
        else if (VirtualUrRtdeFields.RegisterNumber(name, prefix + "double_register_") is int number and >= 0)
        {
            payload.Double(twin.Io.GetNumber(output ? UrIoBanks.OutputFloatRegisters : UrIoBanks.InputFloatRegisters, number));
        }
    }

    /// <summary>32 boolean registers from <paramref name="first"/> as one word, the first in bit 0.</summary>
    private static uint RegisterWord(UrTwinController twin, string bank, int first)
    {
        uint word = 0;
        for (int i = 0; i < 32; i++)
        {
            word |= (twin.Io.GetBit(bank, first + i) ? 1u : 0) << i;
        }
        return word;
    }

    /// <summary>The rotation vector (axis times angle, radians) of a rotation, as UR poses give it.</summary>
    private static Vector RotationVectorOf(Rotation rotation)
    {
        RotationVector rv = rotation.ToRotationVector();
        return new Vector(rv.X * Math.PI / 180, rv.Y * Math.PI / 180, rv.Z * Math.PI / 180);
    }
}
