namespace Machina;

/// <summary>
/// The controller could not run an action (an unreachable target, a joint beyond its limits, a refused instruction) and
/// stopped. Nothing after the action was executed. <see cref="Action"/> names it; the message holds the controller's words.
/// With <see cref="ControllerCode"/> "restarted", a controller restart left the action's outcome unknown and it was not sent
/// again (<see cref="Robot.ResendAfterControllerRestart"/>).
/// </summary>
public sealed class ActionFailedException : MachinaException
{
    /// <summary>Creates the exception for <paramref name="action"/>, with the controller's reason and error code (null when it gives none).</summary>
    public ActionFailedException(RobotAction action, string controllerReason, string? controllerCode)
        : base(Describe(action, controllerReason, controllerCode), controllerReason)
    {
        Action = action ?? throw new ArgumentNullException(nameof(action));
        ControllerReason = controllerReason ?? throw new ArgumentNullException(nameof(controllerReason));
        ControllerCode = string.IsNullOrWhiteSpace(controllerCode) ? null : controllerCode;
    }

    /// <summary>
    /// Creates the exception with a message of its own, for an action whose outcome is not the controller's report (a restart
    /// left it unknown: <c>OnlineSession.RestartedReason</c>).
    /// </summary>
    internal ActionFailedException(RobotAction action, string controllerReason, string? controllerCode, string message)
        : base(message, controllerReason)
    {
        Action = action;
        ControllerReason = controllerReason;
        ControllerCode = controllerCode;
    }

    /// <summary>The action the controller could not run.</summary>
    public RobotAction Action { get; }

    /// <summary>What the controller said, in its own words.</summary>
    public string ControllerReason { get; }

    /// <summary>The controller's error number or code (ABB ERRNO, UR safety status, KUKA message number), or null (also when it gave an empty one).</summary>
    public string? ControllerCode { get; }

    private static string Describe(RobotAction action, string reason, string? code) =>
        $"The controller could not run {action?.ToInstruction()} (id {action?.Id}): {reason}"
        + (string.IsNullOrWhiteSpace(code) ? "" : $" (code {code})") + " Nothing after it was executed.";
}
