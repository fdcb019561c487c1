using System.Net.Sockets;
using System.Security.Cryptography;
using System.Text;

namespace Machina.Simulation.Rws;

/// <summary>
/// The server side of a WebSocket (RFC 6455) as RWS subscriptions use it: the handshake's accept key, unmasked text frames out,
/// masked frames in (a close or a ping is all a subscriber sends).
/// </summary>
internal static class RwsWebSocket
{
    /// <summary>The longest frame payload read from a client, in bytes.</summary>
    public const int MaxIncoming = 64 * 1024;

    /// <summary>The Sec-WebSocket-Accept value for a client's Sec-WebSocket-Key.</summary>
    public static string AcceptKey(string key) =>
        Convert.ToBase64String(SHA1.HashData(Encoding.ASCII.GetBytes(key.Trim() + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11")));

    /// <summary>Writes one unmasked frame of <paramref name="opcode"/> (1 text, 8 close, 10 pong).</summary>
    public static async Task WriteAsync(NetworkStream stream, int opcode, byte[] payload, CancellationToken cancellationToken)
    {
        var frame = new List<byte> { (byte)(0x80 | opcode) };
        if (payload.Length < 126)
        {
            frame.Add((byte)payload.Length);
        }
        else if (payload.Length <= ushort.MaxValue)
        {
            frame.AddRange([126, (byte)(payload.Length >> 8), (byte)payload.Length]);
        }
        else
        {
            frame.Add(127);
            frame.AddRange(Enumerable.Range(0, 8).Select(i => (byte)((long)payload.Length >> (8 * (7 - i)))));
        }
        frame.AddRange(payload);
        await stream.WriteAsync(frame.ToArray(), cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Reads one frame from the client: its opcode and (unmasked) payload; null when the connection ended.</summary>
    public static async Task<(int Opcode, byte[] Payload)?> ReadAsync(NetworkStream stream, CancellationToken cancellationToken)
    {
        byte[]? head = await ReadExactlyAsync(stream, 2, cancellationToken).ConfigureAwait(false);
        if (head is null)
        {
            return null;
        }
        long length = head[1] & 0x7F;
        if (length >= 126)
        {
            byte[]? extended = await ReadExactlyAsync(stream, length == 126 ? 2 : 8, cancellationToken).ConfigureAwait(false);
            if (extended is null)
            {
                return null;
            }
            length = extended.Aggregate(0L, (v, b) => (v << 8) | b);
        }
        if (length > MaxIncoming)
        {
            return null; // more than a subscriber sends: the server ends the connection
        }
        byte[]? mask = (head[1] & 0x80) != 0 ? await ReadExactlyAsync(stream, 4, cancellationToken).ConfigureAwait(false) : [0, 0, 0, 0];
        byte[]? payload = await ReadExactlyAsync(stream, (int)length, cancellationToken).ConfigureAwait(false);
        if (mask is null || payload is null)
        {
            return null;
        }
        for (int i = 0; i < payload.Length; i++)
        {
            payload[i] ^= mask[i % 4];
        }
        return (head[0] & 0x0F, payload);
    }

    private static async Task<byte[]?> ReadExactlyAsync(NetworkStream stream, int count, CancellationToken cancellationToken)
    {
        var buffer = new byte[count];
        int read = 0;
        while (read < count)
        {
            int n = await stream.ReadAsync(buffer.AsMemory(read), cancellationToken).ConfigureAwait(false);
            if (n == 0)
            {
                return null;
            }
            read += n;
        }
        return buffer;
    }
}
