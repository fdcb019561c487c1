using System.Collections.Immutable;

namespace Machina;

/// <summary>
/// The facts the host, Machina's KRL driver (drivers/kuka) and the virtual KUKA controller share: element and attribute names,
/// the driver version and the size of the driver's action ring (docs/protocol-kuka.md).
/// </summary>
internal static class KukaProtocol
{
    /// <summary>Version of the KRL driver this Machina ships (<c>S/@VR</c>); 2.x reports its progress, 2.1 runs a CIRC (action 17), 1.0 was the original's.</summary>
    public const string DriverVersion = "2.1";

    /// <summary>Slots of the driver's action ring: the host never has more actions sent and unacknowledged than this.</summary>
    public const int Capacity = 100;

    /// <summary>Longest message text the driver shows (KRL's message text is a CHAR[80]).</summary>
    public const int MaxTextLength = 80;

    /// <summary>Number of parameters every action carries (<c>V1</c>…<c>V7</c>).</summary>
    public const int ValueCount = 7;

    /// <summary>Number of parameters of a <see cref="KukaActionCode.Circular"/> action: <c>V1</c>…<c>V7</c>, then its auxiliary point in <c>V8</c>…<c>V13</c>.</summary>
    public const int CircularValueCount = 13;

    /// <summary>How many parameters an action of <paramref name="code"/> carries: 13 for a CIRC, 7 for every other.</summary>
    public static int ValueCountOf(KukaActionCode code) => code == KukaActionCode.Circular ? CircularValueCount : ValueCount;

    /// <summary>Root of a batch of actions, host to driver: <c>&lt;DT&gt;&lt;DR&gt;&lt;A …/&gt;…&lt;/DR&gt;&lt;/DT&gt;</c>.</summary>
    public const string Batch = "DT";

    /// <summary>The list of actions inside a batch.</summary>
    public const string Actions = "DR";

    /// <summary>One action: attributes <c>ID</c>, <c>T</c>, <c>V1</c>…<c>V7</c> (a CIRC: …<c>V13</c>), <c>M</c>.</summary>
    public const string Action = "A";

    /// <summary>The driver's state, sent on every connection: version, axes, pose and progress.</summary>
    public const string State = "S";

    /// <summary>An acknowledgement: attribute <c>ID</c>, the action the driver executed.</summary>
    public const string Acknowledgement = "R";

    /// <summary>A failure report: attributes <c>ID</c>, <c>Code</c> and <c>Text</c>, the action the driver could not run before it halted.</summary>
    public const string Failure = "F";

    /// <summary>The driver's answer to <see cref="StopCommand"/>, <see cref="PauseCommand"/> or <see cref="ResumeCommand"/>: <c>&lt;C K="n"/&gt;</c> (1 paused, 2 resumed, 3 stopped).</summary>
    public const string Control = "C";

    /// <summary>Robot.Stop, out of band on the driver's channel: sets $FLAG[4], whose interrupt brakes, fails the action that runs and drops the rest.</summary>
    public const string StopCommand = "<STOP/>";

    /// <summary>Robot.Pause, out of band: sets $FLAG[5], whose interrupt brakes and holds until <see cref="ResumeCommand"/>.</summary>
    public const string PauseCommand = "<PAUSE/>";

    /// <summary>Robot.Resume after a pause: sets $FLAG[6]; the held motion goes on.</summary>
    public const string ResumeCommand = "<RESUME/>";

    /// <summary>A live pose report on the monitor channel (driver port + 1).</summary>
    public const string Pose = "P";

    /// <summary>Host to monitor: how often to report, attribute <c>Ms</c> (milliseconds).</summary>
    public const string MonitorRate = "MON";

    /// <summary>Attribute names of a state or pose report: the axes in degrees, then the pose (mm, degrees).</summary>
    public static readonly ImmutableArray<string> AxisNames = ["A1", "A2", "A3", "A4", "A5", "A6"];

    /// <summary>Attribute names of the action parameters (the last six only on a CIRC).</summary>
    public static readonly ImmutableArray<string> ValueNames = ["V1", "V2", "V3", "V4", "V5", "V6", "V7", "V8", "V9", "V10", "V11", "V12", "V13"];
}

/// <summary>What the KRL driver does with an action (<c>A/@T</c>); the parameters <c>V1</c>…<c>V7</c> are listed per code.</summary>
internal enum KukaActionCode
{
    /// <summary><c>LIN</c> to X, Y, Z (mm), A, B, C (degrees) in V1…V6.</summary>
    Linear = 1,

    /// <summary><c>PTP</c> to the Cartesian pose X, Y, Z, A, B, C in V1…V6.</summary>
    JointToPose = 2,

    /// <summary><c>PTP</c> to axes A1…A6 (degrees) in V1…V6.</summary>
    JointToAxes = 3,

    /// <summary><c>$VEL.CP</c> = V1 (m/s).</summary>
    Speed = 4,

    /// <summary><c>$ACC.CP</c> = V1 (m/s²), or the controller's default when V1 is 0.</summary>
    Acceleration = 5,

    /// <summary><c>$APO.CDIS</c> = V1 (mm); 0 stops exactly at each target.</summary>
    Precision = 6,

    /// <summary><c>WAIT SEC</c> V1 (seconds).</summary>
    Wait = 7,

    /// <summary>Shows the text <c>M</c> as a notification message.</summary>
    Message = 8,

    /// <summary><c>$TOOL</c> = the frame X, Y, Z, A, B, C in V1…V6.</summary>
    AttachTool = 9,

    /// <summary><c>$TOOL = $NULLFRAME</c>.</summary>
    DetachTool = 10,

    /// <summary><c>$OUT[V1]</c> = V2 (1 true, 0 false).</summary>
    DigitalOutput = 11,

    /// <summary><c>$ANOUT[V1]</c> = V2 (−1 to 1).</summary>
    AnalogOutput = 12,

    /// <summary>Speed V1 (m/s), acceleration V2 (m/s², 0 = default) and precision V3 (mm) at once: settings restored by a pop.</summary>
    Settings = 13,

    /// <summary>Wait until <c>$IN[V1]</c> is V2 (1 true, 0 false), at most V3 ms (0 = no limit; timer 15 counts).</summary>
    WaitInput = 14,

    /// <summary>Read <c>$IN[V1]</c>: its acknowledgement carries the value, <c>&lt;R ID="" V="1"/&gt;</c> (1 true, 0 false).</summary>
    ReadDigital = 15,

    /// <summary>Read <c>$ANIN[V1]</c> (−1 to 1): its acknowledgement carries the value, <c>&lt;R ID="" V=""/&gt;</c>.</summary>
    ReadAnalog = 16,

    /// <summary>
    /// <c>CIRC</c> through the auxiliary point X, Y, Z, A, B, C in V8…V13 to X, Y, Z, A, B, C in V1…V6, as the KRL compiler writes
    /// an arc (the controller does not use the auxiliary point's orientation). Only this action carries V8…V13.
    /// </summary>
    Circular = 17,
}
