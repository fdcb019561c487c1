namespace Machina.Simulation;

/// <summary>A snapshot of what the virtual UR controller believes about its robot, in Machina units.</summary>
public sealed record VirtualUrState : VirtualRobotState
{
    /// <summary>Joint speed in °/s for joint moves. Starts at 20, like the driver.</summary>
    public double JointSpeed { get; init; } = 20;

    /// <summary>TCP acceleration in mm/s².</summary>
    public double Acceleration { get; init; } = 1200;

    /// <summary>Joint acceleration in °/s².</summary>
    public double JointAcceleration { get; init; } = 80;

    /// <summary>Payload in kg set with the tool.</summary>
    public double Payload { get; init; }
}
