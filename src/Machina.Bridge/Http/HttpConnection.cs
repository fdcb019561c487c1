using System.Security.Cryptography;
using System.Text;

namespace Machina.Bridge;

/// <summary>Reads one request head from a connection and writes plain responses and the WebSocket handshake answer.</summary>
internal static class HttpConnection
{
    /// <summary>The GUID that RFC 6455 appends to the client's key before hashing.</summary>
    private const string WebSocketGuid = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";

    /// <summary>
    /// Reads bytes up to and including the empty line that ends the head, one at a time so that nothing after it is consumed
    /// (the WebSocket reads the rest). Returns null when the client closed first, or the head is longer than the limit.
    /// </summary>
    internal static async Task<(byte[]? Head, bool TooLong)> ReadHeadAsync(Stream stream, CancellationToken cancellationToken)
    {
        var head = new MemoryStream(512);
        var one = new byte[1];
        int newlines = 0;
        while (true)
        {
            int n = await stream.ReadAsync(one, cancellationToken).ConfigureAwait(false);
            if (n == 0)
            {
                return (null, false);
            }
            byte b = one[0];
            head.WriteByte(b);
            if (head.Length > HttpRequestHead.MaxBytes)
            {
                return (null, true);
            }
            if (b == '\n')
            {
                if (++newlines == 2)
                {
                    return (head.ToArray(), false);
                }
            }
            else if (b != '\r')
            {
                newlines = 0;
            }
        }
    }

    /// <summary>The Sec-WebSocket-Accept value for a client's Sec-WebSocket-Key: base64(SHA-1(key + GUID)).</summary>
    internal static string AcceptKey(string clientKey) =>
        Convert.ToBase64String(SHA1.HashData(Encoding.ASCII.GetBytes(clientKey + WebSocketGuid)));

    /// <summary>True when the key is the base64 text of 16 bytes, as RFC 6455 requires.</summary>
    internal static bool IsValidKey(string? key)
    {
        if (key is null || key.Length != 24)
        {
            return false;
        }
        Span<byte> bytes = stackalloc byte[18];
        return Convert.TryFromBase64String(key, bytes, out int written) && written == 16;
    }

    /// <summary>The 101 answer that switches the connection to the WebSocket protocol.</summary>
    internal static byte[] SwitchingProtocols(string clientKey) => Encoding.ASCII.GetBytes(
        "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: " + AcceptKey(clientKey) + "\r\n\r\n");

    /// <summary>A complete response that closes the connection; with <paramref name="headOnly"/> (a HEAD request) the body is left out but still counted.</summary>
    internal static byte[] Response(int status, string reason, string contentType, ReadOnlySpan<byte> body, string extraHeaders = "", bool headOnly = false)
    {
        string head = $"HTTP/1.1 {status} {reason}\r\nContent-Type: {contentType}\r\nContent-Length: {body.Length}\r\n" +
            "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n" + extraHeaders + "\r\n";
        byte[] bytes = new byte[Encoding.ASCII.GetByteCount(head) + (headOnly ? 0 : body.Length)];
        int at = Encoding.ASCII.GetBytes(head, bytes);
        if (!headOnly)
        {
            body.CopyTo(bytes.AsSpan(at));
        }
        return bytes;
    }

    /// <summary>A plain-text error response that closes the connection.</summary>
    internal static byte[] Error(int status, string reason, string message, string extraHeaders = "") =>
        Response(status, reason, "text/plain; charset=utf-8", Encoding.UTF8.GetBytes(message + "\n"), extraHeaders);
}
