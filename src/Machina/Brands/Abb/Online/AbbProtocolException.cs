namespace Machina;

/// <summary>
/// The ABB controller sent something that does not follow the Machina driver protocol
/// (for example a message that is neither an acknowledgement nor a data message).
/// </summary>
public sealed class AbbProtocolException : MachinaException
{
    /// <summary>Creates the exception with a message and the offending text exactly as received.</summary>
    public AbbProtocolException(string message, string? receivedText) : base(message, receivedText) { }
}
