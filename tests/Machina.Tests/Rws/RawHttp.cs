using System.Net;
using System.Net.Sockets;
using System.Security.Cryptography;
using System.Text;

namespace Machina.Tests.Rws;

/// <summary>A bare HTTP/1.1 client for tests of the RWS twin: sends exactly the bytes given, reads one answer (head and Content-Length body).</summary>
internal sealed class RawHttp : IDisposable
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(15);
    private readonly TcpClient _client = new();
    private readonly List<byte> _received = [];

    private RawHttp() { }

    public static async Task<RawHttp> ConnectAsync(int port)
    {
        var http = new RawHttp();
        using var cts = new CancellationTokenSource(Limit);
        await http._client.ConnectAsync(IPAddress.Loopback, port, cts.Token);
        return http;
    }

    public NetworkStream Stream => _client.GetStream();

    public Task SendAsync(string text) => Stream.WriteAsync(Encoding.Latin1.GetBytes(text)).AsTask();

    /// <summary>One request on a new connection: its answer.</summary>
    public static async Task<RawAnswer> RequestAsync(int port, string request)
    {
        using RawHttp http = await ConnectAsync(port);
        await http.SendAsync(request);
        return await http.ReadAnswerAsync();
    }

    /// <summary>The next answer (throws when the connection closes before it is complete, or after 15 s).</summary>
    public async Task<RawAnswer> ReadAnswerAsync()
    {
        using var cts = new CancellationTokenSource(Limit);
        var buffer = new byte[4096];
        while (true)
        {
            string text = Encoding.Latin1.GetString([.. _received]);
            int end = text.IndexOf("\r\n\r\n", StringComparison.Ordinal);
            if (end >= 0)
            {
                string[] lines = text[..end].Split("\r\n");
                int length = lines.Where(l => l.StartsWith("Content-Length:", StringComparison.OrdinalIgnoreCase))
                    .Select(l => int.Parse(l[15..].Trim(), Num.Inv)).FirstOrDefault();
                if (text.Length >= end + 4 + length)
                {
                    _received.RemoveRange(0, end + 4 + length);
                    return new RawAnswer(int.Parse(lines[0].Split(' ')[1], Num.Inv), lines[1..], text.Substring(end + 4, length));
                }
            }
            int n = await Stream.ReadAsync(buffer, cts.Token);
            if (n == 0)
            {
                throw new IOException("The server closed the connection before its answer was complete: " + text);
            }
            _received.AddRange(buffer.AsSpan(0, n).ToArray());
        }
    }

    /// <summary>True when the server closed the connection (within 15 s).</summary>
    public async Task<bool> ClosedAsync()
    {
        using var cts = new CancellationTokenSource(Limit);
        var buffer = new byte[4096];
        try
        {
            while (await Stream.ReadAsync(buffer, cts.Token) > 0)
            {
            }
            return true;
        }
        catch (IOException)
        {
            return true;
        }
        catch (OperationCanceledException)
        {
            return false;
        }
    }

    public void Dispose() => _client.Dispose();

    /// <summary>The Authorization header answering <paramref name="nonce"/> for <paramref name="method"/> <paramref name="uri"/> (RFC 7616, MD5, qop=auth).</summary>
    public static string Digest(string nonce, string method, string uri, string nc, string user = "Default User", string password = "robotics")
    {
        const string realm = "validusers@robotcontroller.com";
        const string cnonce = "0a4f113b";
        string ha1 = Md5($"{user}:{realm}:{password}");
        string ha2 = Md5($"{method}:{uri}");
        string response = Md5($"{ha1}:{nonce}:{nc}:{cnonce}:auth:{ha2}");
        return $"Digest username=\"{user}\", realm=\"{realm}\", nonce=\"{nonce}\", uri=\"{uri}\", qop=auth, nc={nc}, cnonce=\"{cnonce}\", response=\"{response}\"";
    }

#pragma warning disable CA5351 // RWS 1.0 digest is MD5.
    private static string Md5(string text) => Convert.ToHexString(MD5.HashData(Encoding.UTF8.GetBytes(text))).ToLowerInvariant();
#pragma warning restore CA5351
}

/// <summary>An answer: status, header lines and body.</summary>
internal sealed record RawAnswer(int Status, string[] Headers, string Body)
{
    /// <summary>The nonce of a WWW-Authenticate challenge.</summary>
    public string Nonce => Header("WWW-Authenticate").Split("nonce=\"")[1].Split('"')[0];

    /// <summary>The value of the header <paramref name="name"/> (empty when absent).</summary>
    public string Header(string name) => Headers.Where(h => h.StartsWith(name + ":", StringComparison.OrdinalIgnoreCase))
        .Select(h => h[(name.Length + 1)..].Trim()).FirstOrDefault() ?? "";
}
