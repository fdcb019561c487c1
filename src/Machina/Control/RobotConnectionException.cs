namespace Machina;

/// <summary>
/// The link to a controller failed: it could not be reached, closed the connection, stopped answering, acknowledged an
/// action that was not waiting, or the robot was disconnected while a call waited. <c>ReceivedText</c> holds what the
/// controller sent, when that caused the failure.
/// </summary>
public sealed class RobotConnectionException : MachinaException
{
    /// <summary>Creates the exception with a message for the user.</summary>
    public RobotConnectionException(string message) : base(message) { }

    /// <summary>Creates the exception with a message and the underlying cause.</summary>
    public RobotConnectionException(string message, Exception? innerException) : base(message, innerException) { }

    /// <summary>Creates the exception with a message and the text received from the controller that caused it.</summary>
    public RobotConnectionException(string message, string? receivedText) : base(message, receivedText) { }
}
