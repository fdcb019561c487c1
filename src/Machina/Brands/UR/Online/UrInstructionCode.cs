namespace Machina;

/// <summary>Instruction codes of the UR driver protocol (spec online §7.3; docs/protocol-ur.md), the original's numbering.</summary>
internal enum UrInstructionCode
{
    /// <summary><c>movel</c> to a pose: X Y Z (1e-4 m) RX RY RZ (1e-4 rad).</summary>
    MoveL = 1,

    /// <summary><c>movej</c> to a pose: X Y Z RX RY RZ.</summary>
    MoveJPose = 2,

    /// <summary><c>movej</c> to joints: J1..J6 (1e-4 rad).</summary>
    MoveJJoints = 3,

    /// <summary>TCP speed (1e-4 m/s).</summary>
    TcpSpeed = 4,

    /// <summary>TCP acceleration (1e-4 m/s²).</summary>
    TcpAcceleration = 5,

    /// <summary>Joint speed (1e-4 rad/s).</summary>
    JointSpeed = 6,

    /// <summary>Joint acceleration (1e-4 rad/s²).</summary>
    JointAcceleration = 7,

    /// <summary>Blend radius (1e-4 m).</summary>
    Blend = 8,

    /// <summary><c>sleep</c> (ms).</summary>
    Sleep = 9,

    /// <summary>Tool: X Y Z (1e-4 m) RX RY RZ (1e-4 rad) and payload (g).</summary>
    SetTool = 12,

    /// <summary>Digital output: pin, on (0/1), tool (0/1).</summary>
    SetDigitalOut = 13,

    /// <summary>Analog output: pin, value (1e-6).</summary>
    SetAnalogOut = 14,

    /// <summary>TCP speed (1e-4 m/s) and the same number as joint speed in °/s.</summary>
    AllSpeed = 15,

    /// <summary>TCP acceleration (1e-4 m/s²) and the same number as joint acceleration in °/s².</summary>
    AllAcceleration = 16,

    /// <summary><c>movep</c> to a pose.</summary>
    MoveP = 17,

    /// <summary>Wait for a digital input: pin, value (0/1), tool (0/1), time limit (ms, 0 = none).</summary>
    WaitDigitalIn = 18,

    /// <summary>Read a digital input: pin, tool (0/1); answered with <see cref="UrWire.ResponseInput"/> before the acknowledgement.</summary>
    ReadDigitalIn = 19,

    /// <summary>Read an analog input: pin, tool (0/1); answered with <see cref="UrWire.ResponseInput"/> before the acknowledgement.</summary>
    ReadAnalogIn = 20,

    /// <summary>
    /// <c>movec</c> through a pose to a pose (an arc): the via pose X Y Z RX RY RZ, then the target pose X Y Z RX RY RZ, run as
    /// <c>movec(via, to, a, v, r, mode=0)</c> with the current tool speed, acceleration and blend, as the URScript compiler writes it.
    /// </summary>
    MoveC = 21,
}
