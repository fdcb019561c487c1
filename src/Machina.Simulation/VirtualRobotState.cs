namespace Machina.Simulation;

/// <summary>
/// What every virtual controller believes about its robot, in Machina units; each brand's state adds its own settings.
/// With a robot model, <see cref="Position"/>/<see cref="Rotation"/> and <see cref="Joints"/> always agree through its kinematics.
/// </summary>
public abstract record VirtualRobotState
{
    /// <summary>TCP position in mm (the flange when no tool is attached) of the last target reached or being reached.</summary>
    public required Vector Position { get; init; }

    /// <summary>TCP orientation matching <see cref="Position"/>.</summary>
    public required Rotation Rotation { get; init; }

    /// <summary>Joint angles in degrees.</summary>
    public required Joints Joints { get; init; }

    /// <summary>TCP speed in mm/s used by linear moves.</summary>
    public double Speed { get; init; } = 20;

    /// <summary>Blend (zone) radius in mm; 0 means the robot stops exactly at each target.</summary>
    public double Zone { get; init; }

    /// <summary>The attached tool's TCP relative to the flange (mm), or null when no tool is attached.</summary>
    public Pose? Tool { get; init; }

    /// <summary>Digital outputs set so far, by signal name (true = on).</summary>
    public IReadOnlyDictionary<string, bool> DigitalOutputs { get; init; } = new Dictionary<string, bool>();

    /// <summary>Analog outputs set so far, by signal name.</summary>
    public IReadOnlyDictionary<string, double> AnalogOutputs { get; init; } = new Dictionary<string, double>();

    /// <summary>The TCP pose (position and orientation together).</summary>
    public Pose Pose => new(Position, Rotation);
}
