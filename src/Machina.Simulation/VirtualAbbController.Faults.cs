using System.Globalization;
using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>The largest request id the driver reads (the host sends ids modulo this).</summary>
    private const int MaxId = 8_388_608;

    /// <summary>Fault injection: send any text on the driver socket (for example garbage); false when no client is connected.</summary>
    public Task<bool> SendRawAsync(string text, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(text);
        return SendToClientAsync(Encoding.ASCII.GetBytes(text), cancellationToken);
    }

    /// <summary>Fault injection: send an acknowledgement for any id (for example one never requested); false when no client is connected.</summary>
    public Task<bool> SendAcknowledgementAsync(int id, int code, CancellationToken cancellationToken = default) =>
        SendToClientAsync(AcknowledgementOf(id, code), cancellationToken);

    private protected override byte[] AcknowledgementBytes(int id) => AcknowledgementOf(id, 0);

    /// <summary>An acknowledgement as the driver's Acknowledge writes it: <c>@id code;</c>, or <c>code;</c> for id 0.</summary>
    private static byte[] AcknowledgementOf(int id, int code) => Encoding.ASCII.GetBytes(id == 0
        ? code.ToString(CultureInfo.InvariantCulture) + ";"
        : "@" + id.ToString(CultureInfo.InvariantCulture) + " " + code.ToString(CultureInfo.InvariantCulture) + ";");

    /// <summary>A statement that is neither an acknowledgement (<c>@</c>) nor data (<c>$</c>).</summary>
    private protected override byte[] GarbageBytes(Random random)
    {
        const string alphabet = "#!%&*?xyz019 ";
        var text = new StringBuilder("#");
        for (int i = random.Next(2, 12); i > 0; i--)
        {
            text.Append(alphabet[random.Next(alphabet.Length)]);
        }
        return Encoding.ASCII.GetBytes(text.Append(';').ToString());
    }

    /// <summary>Ids are sent modulo <see cref="MaxId"/>: one far ahead, within that range.</summary>
    private protected override int UnknownId(int id) => (id + 1_000_000 - 1) % MaxId + 1;
}
