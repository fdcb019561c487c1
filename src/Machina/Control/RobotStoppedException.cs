namespace Machina;

/// <summary>
/// The controller stopped on its own (a protective or emergency stop) while actions were waiting. Nothing more is sent and
/// nothing is lost: clear the cause, then call <c>Robot.Resume</c> (or resume at the pendant) and the rest runs.
/// </summary>
public sealed class RobotStoppedException : MachinaException
{
    /// <summary>Creates the exception with a message for the user.</summary>
    public RobotStoppedException(string message) : base(message) { }

    /// <summary>Creates the exception with a message and what the controller reported.</summary>
    public RobotStoppedException(string message, string? receivedText) : base(message, receivedText) { }
}
