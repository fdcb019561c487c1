using System.Buffers.Binary;
using System.Text;

namespace Machina.Simulation;

/// <summary>
/// The packages of a UR's primary, secondary and real-time client interfaces as the virtual UR sends them, written from UR's
/// "Client interfaces" description (software 5.x): every package is a big-endian int32 size (itself included), a message type,
/// then its content; a robot state package (type 16) holds sub-packages, each with its own int32 size and uint8 type.
/// </summary>
internal static class VirtualUrClientPackages
{
    /// <summary>Message type of a robot state package.</summary>
    public const byte RobotState = 16;

    /// <summary>Message type of a robot message (version, text, runtime exception…).</summary>
    public const byte RobotMessage = 20;

    /// <summary>Robot message kinds: version 3, text 0.</summary>
    public const byte VersionKind = 3, TextKind = 0;

    /// <summary>Source of a robot message the controller sends about itself: -2.</summary>
    public const sbyte ControllerSource = -2;

    /// <summary>Robot state sub-package types.</summary>
    public const byte RobotModeData = 0, JointData = 1, ToolData = 2, MasterboardData = 3, CartesianInfo = 4, KinematicsInfo = 5,
        ConfigurationData = 6, ForceModeData = 7, AdditionalInfo = 8;

    /// <summary>Doubles of a real-time package: 152 from software 5 on (1220 bytes with the size), 139 before (1116 bytes).</summary>
    public static int RealtimeDoubles(Version version) => version.Major >= 5 ? 152 : 139;

    /// <summary>
    /// The version message a controller sends first on a primary or secondary connection: robot message (20), timestamp,
    /// source, kind 3, project name length and "URControl", major and minor (uint8), bugfix and build (int32), build date text.
    /// </summary>
    public static byte[] Version(ulong timestamp, Version version)
    {
        byte[] name = Encoding.ASCII.GetBytes("URControl");
        byte[] date = Encoding.ASCII.GetBytes("01-01-2024, 00:00:00");
        var w = new Writer(15 + 1 + name.Length + 2 + 8 + date.Length);
        w.Int32(0);
        w.Byte(RobotMessage);
        w.UInt64(timestamp);
        w.Byte(unchecked((byte)ControllerSource));
        w.Byte(VersionKind);
        w.Byte((byte)name.Length);
        w.Bytes(name);
        w.Byte((byte)version.Major);
        w.Byte((byte)version.Minor);
        w.Int32(Math.Max(0, version.Build));
        w.Int32(Math.Max(0, version.Revision));
        w.Bytes(date);
        return w.Sized();
    }

    /// <summary>A text message (robot message kind 0) from the controller: what the pendant's log shows.</summary>
    public static byte[] Text(ulong timestamp, string text)
    {
        byte[] words = Encoding.UTF8.GetBytes(text);
        var w = new Writer(15 + words.Length);
        w.Int32(0);
        w.Byte(RobotMessage);
        w.UInt64(timestamp);
        w.Byte(unchecked((byte)ControllerSource));
        w.Byte(TextKind);
        w.Bytes(words);
        return w.Sized();
    }

    /// <summary>One robot state package (type 16) with the robot mode, joint, tool, masterboard, cartesian, kinematics, configuration, force mode and additional info sub-packages.</summary>
    public static byte[] State(VirtualUrClientState s, VirtualUrArmFacts arm)
    {
        var w = new Writer(1400);
        w.Int32(0);
        w.Byte(RobotState);

        int start = w.Begin(RobotModeData);
        w.UInt64((ulong)(s.Time * 1000));
        w.Bool(false); // a real robot connected: no, a simulated one
        w.Bool(true); // real robot enabled
        w.Bool(s.PowerOn);
        w.Bool(s.SafetyMode == 7);
        w.Bool(s.SafetyMode == 3);
        w.Bool(s.ProgramRunning);
        w.Bool(s.ProgramPaused);
        w.Byte((byte)s.RobotMode);
        w.Byte(0); // control mode: position
        w.Double(s.SpeedFraction); // target speed fraction
        w.Double(s.SpeedFraction); // speed scaling
        w.Double(1); // target speed fraction limit
        w.Byte(0); // reserved
        w.End(start);

        start = w.Begin(JointData);
        byte jointMode = (byte)(s.RobotMode == 7 ? 253 : s.PowerOn ? 255 : 239); // running, idle, power off
        for (int i = 0; i < 6; i++)
        {
            w.Double(s.Q[i]);
            w.Double(s.Q[i]);
            w.Double(s.Qd[i]);
            w.Float(0); // current
            w.Float(s.PowerOn ? 48 : 0); // voltage
            w.Float(30); // motor temperature
            w.Float(0); // deprecated
            w.Byte(jointMode);
        }
        w.End(start);

        start = w.Begin(ToolData);
        w.Byte(0);
        w.Byte(0);
        w.Double(s.ToolAnalogIn[0]);
        w.Double(s.ToolAnalogIn[1]);
        w.Float(s.PowerOn ? 48 : 0);
        w.Byte(0); // tool output voltage
        w.Float(0);
        w.Float(30);
        w.Byte(jointMode);
        w.End(start);

        start = w.Begin(MasterboardData);
        w.Int32((int)s.DigitalInputs);
        w.Int32((int)s.DigitalOutputs);
        w.Byte(0);
        w.Byte(0);
        w.Double(s.AnalogIn[0]);
        w.Double(s.AnalogIn[1]);
        w.Byte(0);
        w.Byte(0);
        w.Double(s.AnalogOut[0]);
        w.Double(s.AnalogOut[1]);
        w.Float(35); // masterboard temperature
        w.Float(s.PowerOn ? 48 : 0);
        w.Float(0);
        w.Float(0);
        w.Byte((byte)s.SafetyMode);
        w.Byte(0); // not in reduced mode
        w.Byte(0); // no Euromap67 interface
        w.Int32(0); // not used
        w.Byte(0); // operational mode selector input
        w.Byte(0); // three-position enabling device input
        w.Byte(0); // not used
        w.End(start);

        start = w.Begin(CartesianInfo);
        w.Doubles(s.Tcp);
        w.Doubles(s.TcpOffset);
        w.End(start);

        start = w.Begin(KinematicsInfo);
        for (int i = 0; i < 6; i++)
        {
            w.Int32(0); // checksum
        }
        w.Doubles(new double[6]); // theta
        w.Doubles(arm.DhA);
        w.Doubles(arm.DhD);
        w.Doubles(arm.DhAlpha);
        w.Int32(0); // calibration status: ok
        w.End(start);

        start = w.Begin(ConfigurationData);
        for (int i = 0; i < 6; i++)
        {
            w.Double(arm.MinJoints[i]);
            w.Double(arm.MaxJoints[i]);
        }
        for (int i = 0; i < 6; i++)
        {
            w.Double(arm.MaxSpeeds[i]);
            w.Double(40); // rad/s², the default joint acceleration limit
        }
        w.Double(1.05); // default joint speed, rad/s
        w.Double(1.4); // default joint acceleration, rad/s²
        w.Double(0.25); // default tool speed, m/s
        w.Double(1.2); // default tool acceleration, m/s²
        w.Double(0.001); // eq radius
        w.Doubles(arm.DhA);
        w.Doubles(arm.DhD);
        w.Doubles(arm.DhAlpha);
        w.Doubles(new double[6]);
        w.Int32(arm.ESeries ? 3 : 2); // masterboard version
        w.Int32(arm.ESeries ? 2 : 1); // controller box type
        w.Int32(arm.RobotType);
        w.Int32(arm.ESeries ? 3 : 2); // robot sub type
        w.End(start);

        start = w.Begin(ForceModeData);
        w.Doubles(new double[6]);
        w.Double(0); // dexterity
        w.End(start);

        start = w.Begin(AdditionalInfo);
        w.Bool(false); // freedrive button pressed
        w.Byte(0); // reserved
        w.Bool(false); // freedrive button enabled
        w.Bool(false); // IO enabled freedrive
        w.Byte(0); // reserved
        w.End(start);

        return w.Sized();
    }

    /// <summary>
    /// One real-time package (port 30003): int32 size, then doubles in the client interface's order — time, target and actual
    /// joint values, tool vector and speed, digital inputs, modes, outputs, program state, safety status and, from software 5,
    /// the payload.
    /// </summary>
    public static byte[] Realtime(VirtualUrClientState s, Version version)
    {
        int count = RealtimeDoubles(version);
        var w = new Writer(4 + count * 8);
        w.Int32(4 + count * 8);
        w.Double(s.Time);
        w.Doubles(s.Q); // target q
        w.Doubles(s.Qd); // target qd
        w.ZeroDoubles(6 * 3); // target qdd, current, moment
        w.Doubles(s.Q); // actual q
        w.Doubles(s.Qd); // actual qd
        w.ZeroDoubles(6 * 2); // actual current, control current
        w.Doubles(s.Tcp); // actual tool vector
        w.Doubles(s.TcpSpeed); // actual TCP speed
        w.ZeroDoubles(6); // actual TCP force
        w.Doubles(s.Tcp); // target tool vector
        w.Doubles(s.TcpSpeed); // target TCP speed
        w.Double(s.DigitalInputs);
        for (int i = 0; i < 6; i++)
        {
            w.Double(30); // motor temperatures
        }
        w.Double(0.002); // controller timer
        w.Double(0); // test value
        w.Double(s.RobotMode);
        for (int i = 0; i < 6; i++)
        {
            w.Double(s.RobotMode == 7 ? 253 : s.PowerOn ? 255 : 239); // joint modes
        }
        w.Double(s.SafetyMode);
        w.ZeroDoubles(6);
        w.ZeroDoubles(3); // tool accelerometer
        w.ZeroDoubles(6);
        w.Double(s.SpeedFraction); // speed scaling
        w.Double(0); // linear momentum norm
        w.ZeroDoubles(2);
        w.Double(s.PowerOn ? 48 : 0); // V main
        w.Double(s.PowerOn ? 48 : 0); // V robot
        w.Double(0); // I robot
        for (int i = 0; i < 6; i++)
        {
            w.Double(s.PowerOn ? 48 : 0); // joint voltages
        }
        w.Double(s.DigitalOutputs);
        w.Double(s.ProgramRunning ? (s.ProgramPaused ? 4 : 2) : 1); // program state, as RTDE's runtime_state: 1 stopped, 2 playing, 4 paused
        w.ZeroDoubles(3 + 3); // elbow position and velocity
        w.Double(s.SafetyMode);
        if (count > 139)
        {
            w.ZeroDoubles(3);
            w.Double(s.Payload);
            w.ZeroDoubles(3 + 6); // payload centre of gravity, inertia
        }
        return w.Sized();
    }

    /// <summary>Writes a client interface message: its values, sub-packages each with its int32 size; <see cref="Sized"/> writes the total size into the first int32.</summary>
    private sealed class Writer(int capacity) : VirtualUrWriter(capacity)
    {
        /// <summary>Starts a sub-package: room for its size, then its type; returns where it starts.</summary>
        public int Begin(byte type)
        {
            int start = Length;
            Int32(0);
            Byte(type);
            return start;
        }

        /// <summary>Writes a sub-package's size (header included) at its start.</summary>
        public void End(int start) => BinaryPrimitives.WriteInt32BigEndian(Written(start, 4), Length - start);

        /// <summary>The whole message, its size in the first int32, in a new array.</summary>
        public byte[] Sized()
        {
            BinaryPrimitives.WriteInt32BigEndian(Written(0, 4), Length);
            return All.ToArray();
        }
    }
}
