using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>Fault injection: send any text on the driver socket (for example garbage); false when no client is connected.</summary>
    public Task<bool> SendRawAsync(string text, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(text);
        return SendToClientAsync(Encoding.ASCII.GetBytes(text), cancellationToken);
    }

    /// <summary>Fault injection: send an acknowledgement for any id (for example one never requested); false when no client is connected.</summary>
    public Task<bool> SendAcknowledgementAsync(int id, int code, CancellationToken cancellationToken = default) =>
        SendToClientAsync(Encoding.ASCII.GetBytes(AbbMessageFormat.Acknowledgement(id, code)), cancellationToken);
}
