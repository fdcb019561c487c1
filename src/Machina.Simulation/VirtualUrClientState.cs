namespace Machina.Simulation;

/// <summary>
/// What the client interfaces (primary, secondary, real-time) report of the virtual UR at one instant, in UR's units: metres,
/// radians, seconds. Taken once per period and written to every client of that interface.
/// </summary>
internal sealed record VirtualUrClientState
{
    /// <summary>Controller time in seconds since it started.</summary>
    public double Time { get; init; }

    /// <summary>Joint positions, rad.</summary>
    public required double[] Q { get; init; }

    /// <summary>Joint speeds, rad/s (the motion in progress's; zeros while the arm stands).</summary>
    public required double[] Qd { get; init; }

    /// <summary>Tool centre point speed in the base frame: x, y, z (m/s), then the turn per second as a rotation vector (rad/s).</summary>
    public required double[] TcpSpeed { get; init; }

    /// <summary>Tool centre point pose in the base frame: x, y, z (m), rotation vector (rad).</summary>
    public required double[] Tcp { get; init; }

    /// <summary>Tool centre point offset from the flange: x, y, z (m), rotation vector (rad).</summary>
    public required double[] TcpOffset { get; init; }

    /// <summary>Robot mode (client interface and RTDE): 3 power off, 5 idle, 7 running.</summary>
    public int RobotMode { get; init; } = 7;

    /// <summary>Safety mode: 1 normal, 3 protective stop, 7 robot emergency stop.</summary>
    public int SafetyMode { get; init; } = 1;

    /// <summary>A program runs (playing or paused).</summary>
    public bool ProgramRunning { get; init; }

    /// <summary>The running program is paused.</summary>
    public bool ProgramPaused { get; init; }

    /// <summary>RTDE runtime_state: 1 stopped, 2 playing, 4 paused.</summary>
    public uint RuntimeState { get; init; } = 1;

    /// <summary>Digital inputs: standard 0–7, configurable 8–15, tool 16–17.</summary>
    public uint DigitalInputs { get; init; }

    /// <summary>Digital outputs: standard 0–7, configurable 8–15, tool 16–17.</summary>
    public uint DigitalOutputs { get; init; }

    /// <summary>Standard analog inputs 0 and 1.</summary>
    public required double[] AnalogIn { get; init; }

    /// <summary>Standard analog outputs 0 and 1.</summary>
    public required double[] AnalogOut { get; init; }

    /// <summary>Tool analog inputs 0 and 1.</summary>
    public required double[] ToolAnalogIn { get; init; }

    /// <summary>Payload mass, kg.</summary>
    public double Payload { get; init; }

    /// <summary>Speed slider fraction (0–1).</summary>
    public double SpeedFraction { get; init; } = 1;

    /// <summary>The robot is powered (not in power off).</summary>
    public bool PowerOn => RobotMode >= 4;
}
