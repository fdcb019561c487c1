namespace Machina;

/// <summary>
/// The KUKA controller sent something that does not follow the Machina KRL driver protocol
/// (for example text that is not XML, or an element with a missing or malformed attribute).
/// </summary>
public sealed class KukaProtocolException : MachinaException
{
    /// <summary>Creates the exception with a message and the offending text exactly as received.</summary>
    public KukaProtocolException(string message, string? receivedText) : base(message, receivedText) { }
}
