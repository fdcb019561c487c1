using System.Buffers.Binary;
using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// The payload of one RTDE data package from the interpreter (RTDE guide: recipe id, then each output big-endian in SI units):
    /// the arm's joints and tool centre point, the program's runtime state, modes and status bits, I/O and registers. What the
    /// twin does not model (currents, temperatures, forces, accelerations) reads as a standing arm's: zero, or nominal values.
    /// </summary>
    private byte[] TwinDataPayload(UrTwinController twin, byte recipe, string[] names)
    {
        var payload = new List<byte>(1 + names.Length * 48) { recipe };
        VirtualUrClientState s = ClientState();
        foreach (string name in names)
        {
            switch (name)
            {
                case "timestamp":
                    AddDouble(payload, s.Time); // controller time, as a UR reports it
                    break;
                case "actual_q" or "target_q":
                    AddDoubles(payload, s.Q);
                    break;
                case "actual_TCP_pose" or "target_TCP_pose":
                    AddDoubles(payload, s.Tcp);
                    break;
                case "tcp_offset":
                    AddDoubles(payload, s.TcpOffset);
                    break;
                case "robot_mode":
                    AddInt(payload, s.RobotMode);
                    break;
                case "joint_mode":
                    for (int i = 0; i < 6; i++)
                    {
                        AddInt(payload, s.RobotMode == RunningMode ? 253 : s.PowerOn ? 255 : 239);
                    }
                    break;
                case "safety_mode" or "safety_status":
                    AddInt(payload, s.SafetyMode);
                    break;
                case "runtime_state":
                    AddInt(payload, (int)TwinRuntime(twin));
                    break;
                case "speed_scaling" or "target_speed_fraction":
                    AddDouble(payload, s.SpeedFraction);
                    break;
                case "actual_digital_output_bits":
                    AddLong(payload, s.DigitalOutputs);
                    break;
                case "actual_digital_input_bits":
                    AddLong(payload, s.DigitalInputs);
                    break;
                case "robot_status_bits": // power on, program running, teach button, power button
                    AddInt(payload, (s.PowerOn ? 1 : 0) | (s.ProgramRunning && !s.ProgramPaused ? 2 : 0));
                    break;
                case "safety_status_bits": // normal, reduced, protective stopped, …, robot emergency stopped (bit 6)
                    AddInt(payload, s.SafetyMode switch { ProtectiveStopped => 1 << 2, RobotEmergencyStopped => 1 << 6, _ => 1 });
                    break;
                case "standard_analog_input0" or "standard_analog_input1":
                    AddDouble(payload, s.AnalogIn[name[^1] - '0']);
                    break;
                case "standard_analog_output0" or "standard_analog_output1":
                    AddDouble(payload, s.AnalogOut[name[^1] - '0']);
                    break;
                case "tool_analog_input0" or "tool_analog_input1":
                    AddDouble(payload, s.ToolAnalogIn[name[^1] - '0']);
                    break;
                case "actual_main_voltage" or "actual_robot_voltage":
                    AddDouble(payload, s.PowerOn ? 48 : 0);
                    break;
                case "actual_joint_voltage":
                    AddDoubles(payload, s.PowerOn ? [48, 48, 48, 48, 48, 48] : new double[6]);
                    break;
                case "joint_temperatures":
                    AddDoubles(payload, [30, 30, 30, 30, 30, 30]);
                    break;
                case "tool_temperature":
                    AddDouble(payload, 30);
                    break;
                case "actual_tool_accelerometer":
                    AddDoubles(payload, [0, 0, -9.82]); // a tool pointing down at rest
                    break;
                case "payload":
                    AddDouble(payload, s.Payload);
                    break;
                case "actual_execution_time":
                    AddDouble(payload, 0.002);
                    break;
                case "output_bit_registers0_to_31" or "output_bit_registers32_to_63" or "input_bit_registers0_to_31" or "input_bit_registers32_to_63":
                    string bank = name.StartsWith("output", StringComparison.Ordinal) ? UrIoBanks.OutputBoolRegisters : UrIoBanks.InputBoolRegisters;
                    AddInt(payload, (int)RegisterWord(twin, bank, name.Contains("32_to", StringComparison.Ordinal) ? 32 : 0));
                    break;
                default:
                    AddOther(twin, payload, name);
                    break;
            }
        }
        return [.. payload];
    }

    /// <summary>A register, or an output the twin does not model: zeros of its type.</summary>
    private static void AddOther(UrTwinController twin, List<byte> payload, string name)
    {
        string prefix = name.StartsWith("output_", StringComparison.Ordinal) ? "output_" : "input_";
        bool output = prefix == "output_";
        if (VirtualUrRtdeFields.RegisterNumber(name, prefix + "bit_register_") is int bit and >= 64)
        {
            payload.Add(twin.Io.GetBit(output ? UrIoBanks.OutputBoolRegisters : UrIoBanks.InputBoolRegisters, bit) ? (byte)1 : (byte)0);
        }
        else if (VirtualUrRtdeFields.RegisterNumber(name, prefix + "int_register_") is int integer and >= 0)
        {
            AddInt(payload, (int)twin.Io.GetNumber(output ? UrIoBanks.OutputIntRegisters : UrIoBanks.InputIntRegisters, integer));
        }
        else if (VirtualUrRtdeFields.RegisterNumber(name, prefix + "double_register_") is int number and >= 0)
        {
            AddDouble(payload, twin.Io.GetNumber(output ? UrIoBanks.OutputFloatRegisters : UrIoBanks.InputFloatRegisters, number));
        }
        else
        {
            payload.AddRange(new byte[VirtualUrRtdePackages.SizeOf(VirtualUrRtdeFields.OutputType(name))]);
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

    private static void AddLong(List<byte> to, ulong value)
    {
        Span<byte> bytes = stackalloc byte[8];
        BinaryPrimitives.WriteUInt64BigEndian(bytes, value);
        to.AddRange(bytes);
    }

    /// <summary>The rotation vector (axis times angle, radians) of a rotation, as UR poses give it.</summary>
    private static Vector RotationVectorOf(Rotation rotation)
    {
        RotationVector rv = rotation.ToRotationVector();
        return new Vector(rv.X * Math.PI / 180, rv.Y * Math.PI / 180, rv.Z * Math.PI / 180);
    }

    private static void AddDouble(List<byte> to, double value)
    {
        Span<byte> bytes = stackalloc byte[8];
        BinaryPrimitives.WriteDoubleBigEndian(bytes, value);
        to.AddRange(bytes);
    }

    private static void AddDoubles(List<byte> to, ReadOnlySpan<double> values)
    {
        foreach (double value in values)
        {
            AddDouble(to, value);
        }
    }

    private static void AddInt(List<byte> to, int value)
    {
        Span<byte> bytes = stackalloc byte[4];
        BinaryPrimitives.WriteInt32BigEndian(bytes, value);
        to.AddRange(bytes);
    }
}
