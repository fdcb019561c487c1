using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// An RTDE text message from a client (package 77, as UR's RTDE client library's <c>send_message</c> writes it: the message's
    /// length as uint8 and the message, the source's length and the source, the warning level as uint8), which a UR shows in
    /// its log: the pendant gets "source: message". A package whose lengths do not fit its size shows as an error, as other
    /// malformed RTDE packages do.
    /// </summary>
    private void ShowClientMessage(ReadOnlySpan<byte> payload)
    {
        int messageLength = payload.Length > 0 ? payload[0] : -1;
        int sourceAt = 1 + messageLength;
        int sourceLength = messageLength >= 0 && sourceAt < payload.Length ? payload[sourceAt] : -1;
        if (sourceLength < 0 || sourceAt + 1 + sourceLength + 1 != payload.Length)
        {
            RecordError($"RTDE: a text message of {payload.Length} bytes that does not hold a message, a source and a level.");
            return;
        }
        string message = Encoding.ASCII.GetString(payload.Slice(1, messageLength));
        string source = Encoding.ASCII.GetString(payload.Slice(sourceAt + 1, sourceLength));
        Pendant(source + ": " + message);
    }
}
