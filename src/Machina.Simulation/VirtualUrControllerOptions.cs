namespace Machina.Simulation;

/// <summary>
/// Settings of a <see cref="VirtualUrController"/>. Every property has a usable default: a UR5e at (0, -90, -90, -90, 90, 0)
/// with its script, RTDE and dashboard servers on three consecutive OS-chosen ports of 127.0.0.1 (script P, RTDE P + 1,
/// dashboard P + 2, which is where Machina's host looks when the script port is not 30001-30003).
/// </summary>
public sealed record VirtualUrControllerOptions : VirtualControllerOptions
{
    /// <summary>A UR5e with the tool pointing down.</summary>
    public VirtualUrControllerOptions()
    {
        Model = RobotModels.Get("UR5e");
        InitialJoints = new Joints(0, -90, -90, -90, 90, 0);
    }

    /// <summary>Port that accepts driver scripts (a real controller: 30001-30003), 0 = OS-chosen. Default 0.</summary>
    public int ScriptPort { get; init; }

    /// <summary>More ports that accept scripts, e.g. [30001, 30002] next to 30003. Default none.</summary>
    public IReadOnlyList<int> ExtraScriptPorts { get; init; } = [];

    /// <summary>RTDE port (a real controller: 30004), 0 = OS-chosen (the script port + 1 when that is OS-chosen too). Default 0.</summary>
    public int RtdePort { get; init; }

    /// <summary>Dashboard port (a real controller: 29999), 0 = OS-chosen (the script port + 2 when that is OS-chosen too). Default 0.</summary>
    public int DashboardPort { get; init; }

    /// <summary>
    /// Primary client interface port (a real controller: 30001): the version message on connect, robot state at 10 Hz, robot
    /// messages, and scripts and primary commands in. 0 = OS-chosen; null (the default) = not served.
    /// </summary>
    public int? PrimaryPort { get; init; }

    /// <summary>Secondary client interface port (a real controller: 30002): as the primary, without primary commands. 0 = OS-chosen; null (the default) = not served.</summary>
    public int? SecondaryPort { get; init; }

    /// <summary>Real-time client interface port (a real controller: 30003): the real-time package at 500 Hz (125 Hz before software 5), and scripts in. 0 = OS-chosen; null (the default) = not served.</summary>
    public int? RealtimePort { get; init; }

    /// <summary>
    /// Always true (the default): the controller runs what arrives on its script ports with its URScript interpreter, as a UR
    /// does, and RTDE and the dashboard report the interpreter's arm, registers and program. Kept so that code setting it
    /// compiles; false is refused (the imitation of the driver it selected is gone). Without a <c>Model</c> the arm is a UR5e.
    /// </summary>
    public bool RunsScripts { get; init; } = true;

    /// <summary>
    /// True: the arm starts powered off (robot mode 3), as URSim and a UR that has just booted do: a program runs only after
    /// <c>power on</c> and <c>brake release</c> (dashboard or primary interface); until then each program that arrives is refused
    /// with a message. False (the default, for tests and embedded use): it starts running (mode 7), so a script runs at once.
    /// </summary>
    public bool StartsPoweredOff { get; init; }

    /// <summary>The controller software version RTDE reports; from 5 on RTDE runs up to 500 Hz, before up to 125 Hz. Default 5.11.0.</summary>
    public Version ControllerVersion { get; init; } = new(5, 11, 0);

    /// <summary>
    /// Where a program's <c>socket_open</c> really connects, given where it asks: the network between the controller and the
    /// computer it calls (a router, or a test's proxy that delays or cuts that link). Default null: where it asks.
    /// </summary>
    public Func<System.Net.DnsEndPoint, System.Net.DnsEndPoint>? OutboundRoute { get; init; }

    /// <summary>Where the robot starts without a model: (492, -133, 488) mm with the tool down, about where a UR5e is at those joints.</summary>
    internal static Pose DefaultStart => new(new Vector(492, -133, 488), Rotation.FromQuaternion(0, 1, 0, 0));

    internal override void Validate()
    {
        base.Validate();
        ArgumentNullException.ThrowIfNull(ControllerVersion);
        ArgumentNullException.ThrowIfNull(ExtraScriptPorts);
        if (!RunsScripts)
        {
            throw new ArgumentException("The virtual UR always runs what arrives on its script ports with its URScript interpreter, as a UR does; RunsScripts = false (the former imitation of the driver) is no longer available.");
        }
        foreach (int port in ExtraScriptPorts.Append(ScriptPort).Append(RtdePort).Append(DashboardPort).Append(PrimaryPort ?? 0).Append(SecondaryPort ?? 0).Append(RealtimePort ?? 0))
        {
            if (port is < 0 or > 65535)
            {
                throw new ArgumentException($"A port must be between 0 and 65535, not {port}.");
            }
        }
    }
}
