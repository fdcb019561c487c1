namespace Machina.Simulation;

/// <summary>A snapshot of what the virtual ABB controller believes about its robot, in Machina units.</summary>
public sealed record VirtualAbbState : VirtualRobotState
{
    /// <summary>External axes used with Cartesian targets (RAPID robtarget extax).</summary>
    public required ExternalAxes ExternalAxesCartesian { get; init; }

    /// <summary>External axes used with joint targets (RAPID jointtarget extax).</summary>
    public required ExternalAxes ExternalAxesJoints { get; init; }

    /// <summary>Acceleration limit in m/s² as received (WorldAccLim), or null when off.</summary>
    public double? AccelerationLimit { get; init; }

    /// <summary>TCP offset of the attached tool in mm, or null for tool0 (no tool).</summary>
    public Vector? ToolTcp => Tool?.Position;

    /// <summary>Mass in kg of the attached tool, or null for tool0.</summary>
    public double? ToolWeight { get; init; }

    /// <summary>Work object frame origin in mm, or null for wobj0.</summary>
    public Vector? WorkObjectOrigin { get; init; }

    /// <summary>True when wrist singularity handling is on (SingArea \Wrist).</summary>
    public bool WristSingularityArea { get; init; }
}
