namespace Machina.Simulation;

/// <summary>A snapshot of what the virtual KUKA controller believes about its robot, in Machina units.</summary>
public sealed record VirtualKukaState : VirtualRobotState
{
    /// <summary><c>$ACC.CP</c> in m/s² as received, or null for the controller's own.</summary>
    public double? Acceleration { get; init; }
}
