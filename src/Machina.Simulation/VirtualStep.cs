namespace Machina.Simulation;

/// <summary>What executing one instruction does: the state after it, how long it takes in robot seconds, and whether it moves in joint space.</summary>
/// <param name="State">The state once the instruction is done.</param>
/// <param name="Seconds">Duration in real robot seconds, before the speed factor; 0 for an instant setting.</param>
/// <param name="InJointSpace">True for a joint move (joints interpolated), false for a linear move or no motion.</param>
internal readonly record struct VirtualStep(VirtualRobotState State, double Seconds, bool InJointSpace = false);

/// <summary>
/// Thrown by a brand's planner for an instruction the simulated robot cannot execute: the controller logs it and keeps serving,
/// or, for a brand whose driver stops on it (<c>StopsOnRefusalAsync</c>), reports it and stops its program.
/// </summary>
internal sealed class VirtualRefusalException(string message, VirtualRefusalKind kind = VirtualRefusalKind.Other) : Exception(message)
{
    /// <summary>What kind of limit the instruction ran into, for the brand to pick its controller's error.</summary>
    public VirtualRefusalKind Kind { get; } = kind;
}

/// <summary>The kinds of limits a virtual robot refuses an instruction for.</summary>
internal enum VirtualRefusalKind
{
    /// <summary>Anything else (an unknown instruction, a duration no controller can time).</summary>
    Other,

    /// <summary>A Cartesian target outside the arm's reach (or no joint solution within its limits).</summary>
    Reach,

    /// <summary>A joint target beyond the arm's joint limits.</summary>
    JointLimits,

    /// <summary>A motion with a speed of 0 or less: it would never end.</summary>
    Speed,

    /// <summary>An output number the controller does not have.</summary>
    Output,

    /// <summary>A value an output cannot take (an analog value beyond its range).</summary>
    OutputValue,
}
