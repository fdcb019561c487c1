namespace Machina.Simulation;

/// <summary>A snapshot of what the virtual ABB controller believes about its robot, in Machina units.</summary>
public sealed record VirtualAbbState
{
    /// <summary>Flange (or, with a tool attached, TCP) position in mm of the last target reached or being reached.</summary>
    public required Vector Position { get; init; }

    /// <summary>Orientation matching <see cref="Position"/>.</summary>
    public required Rotation Rotation { get; init; }

    /// <summary>Joint angles in degrees.</summary>
    public required Joints Joints { get; init; }

    /// <summary>External axes used with Cartesian targets (RAPID robtarget extax).</summary>
    public required ExternalAxes ExternalAxesCartesian { get; init; }

    /// <summary>External axes used with joint targets (RAPID jointtarget extax).</summary>
    public required ExternalAxes ExternalAxesJoints { get; init; }

    /// <summary>TCP speed in mm/s (RAPID speeddata v_tcp). Starts at 20, like the driver's v20.</summary>
    public double Speed { get; init; } = 20;

    /// <summary>Zone radius in mm; 0 means fine. Starts at 5, like the driver's z5.</summary>
    public double Zone { get; init; } = 5;

    /// <summary>Acceleration limit in m/s² as received (WorldAccLim), or null when off.</summary>
    public double? AccelerationLimit { get; init; }

    /// <summary>Name-less description of the attached tool: TCP offset in mm, or null for tool0 (no tool).</summary>
    public Vector? ToolTcp { get; init; }

    /// <summary>Mass in kg of the attached tool, or null for tool0.</summary>
    public double? ToolWeight { get; init; }

    /// <summary>Work object frame origin in mm, or null for wobj0.</summary>
    public Vector? WorkObjectOrigin { get; init; }

    /// <summary>True when wrist singularity handling is on (SingArea \Wrist).</summary>
    public bool WristSingularityArea { get; init; }

    /// <summary>Digital outputs set so far, by signal name (true = 1).</summary>
    public IReadOnlyDictionary<string, bool> DigitalOutputs { get; init; } = new Dictionary<string, bool>();

    /// <summary>Analog outputs set so far, by signal name.</summary>
    public IReadOnlyDictionary<string, double> AnalogOutputs { get; init; } = new Dictionary<string, double>();
}
