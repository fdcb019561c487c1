namespace Machina;

/// <summary>
/// Thrown when an action is well-formed but cannot be applied to the robot's current state, e.g. a relative move while the
/// position is still unknown, or attaching a tool that was never defined. The robot's state is left unchanged.
/// </summary>
public sealed class ActionRefusedException : InvalidOperationException
{
    /// <summary>Creates the exception for <paramref name="action"/> with the reason.</summary>
    public ActionRefusedException(RobotAction action, string reason)
        : base($"Cannot apply \"{action.ToInstruction()}\": {reason}")
    {
        Action = action;
        Reason = reason;
    }

    /// <summary>The refused action.</summary>
    public RobotAction Action { get; }

    /// <summary>Why it was refused, in plain words.</summary>
    public string Reason { get; }
}
