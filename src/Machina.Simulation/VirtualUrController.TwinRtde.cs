using System.Buffers.Binary;
using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// The payload of one RTDE data package from the interpreter (RTDE guide: recipe id, then each output big-endian in SI units):
    /// the arm's joints and tool centre point, the program's runtime state, the output registers and digital outputs it wrote.
    /// </summary>
    private byte[] TwinDataPayload(UrTwinController twin, byte recipe, string[] names)
    {
        var payload = new List<byte>(1 + names.Length * 48) { recipe };
        Joints joints = twin.JointsNow(); // part-way through a motion, on its speed profile
        Pose tcp = twin.Arm.Model.Kinematics.Forward(joints) * twin.Arm.ToolCenter;
        Vector rv = RotationVectorOf(tcp.Rotation);
        double[] pose = [tcp.Position.X / 1000, tcp.Position.Y / 1000, tcp.Position.Z / 1000, rv.X, rv.Y, rv.Z];
        double[] q = [.. joints.ToArray().Select(d => d * Math.PI / 180)];
        Span<byte> eight = stackalloc byte[8];
        foreach (string name in names)
        {
            switch (name)
            {
                case "timestamp":
                    AddDouble(payload, Clock.GetElapsedTime(0).TotalSeconds); // controller time, as a UR reports it
                    break;
                case "actual_q" or "target_q":
                    AddDoubles(payload, q);
                    break;
                case "actual_TCP_pose" or "target_TCP_pose":
                    AddDoubles(payload, pose);
                    break;
                case "actual_qd" or "actual_TCP_speed":
                    AddDoubles(payload, new double[6]);
                    break;
                case "robot_mode":
                    AddInt(payload, RobotMode);
                    break;
                case "safety_mode" or "safety_status":
                    AddInt(payload, SafetyStatus);
                    break;
                case "runtime_state":
                    AddInt(payload, (int)TwinRuntime(twin));
                    break;
                case "speed_scaling" or "target_speed_fraction":
                    AddDouble(payload, 1);
                    break;
                case "actual_digital_output_bits":
                    ulong bits = 0;
                    for (int i = 0; i < 8; i++)
                    {
                        bits |= (twin.Io.GetBit(UrIoBanks.StandardOut, i) ? 1UL : 0) << i;
                        bits |= (twin.Io.GetBit(UrIoBanks.ConfigurableOut, i) ? 1UL : 0) << (8 + i);
                    }
                    for (int i = 0; i < 2; i++)
                    {
                        bits |= (twin.Io.GetBit(UrIoBanks.ToolOut, i) ? 1UL : 0) << (16 + i);
                    }
                    BinaryPrimitives.WriteUInt64BigEndian(eight, bits);
                    payload.AddRange(eight);
                    break;
                default: // output_int_register_N (TypeOf accepted only these)
                    int register = int.Parse(name.AsSpan("output_int_register_".Length), Num.Inv);
                    AddInt(payload, (int)twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, register));
                    break;
            }
        }
        return [.. payload];
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
