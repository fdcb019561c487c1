namespace Machina;

/// <summary>
/// Base type for failures of the link to a robot or of the robot controller itself
/// (unexpected data, lost connection, refused instruction). Carries what was received, when known.
/// Abstract: each failure has its own sealed type (for example <see cref="AbbProtocolException"/>).
/// </summary>
public abstract class MachinaException : Exception
{
    /// <summary>Creates an exception with a message for the user.</summary>
    protected MachinaException(string message) : base(message) { }

    /// <summary>Creates an exception with a message and the underlying cause.</summary>
    protected MachinaException(string message, Exception? innerException) : base(message, innerException) { }

    /// <summary>Creates an exception with a message and the text received from the controller that caused it.</summary>
    protected MachinaException(string message, string? receivedText, Exception? innerException = null) : base(message, innerException)
    {
        ReceivedText = receivedText;
    }

    /// <summary>The text received from the controller that caused the failure, or null when not applicable.</summary>
    public string? ReceivedText { get; }
}
