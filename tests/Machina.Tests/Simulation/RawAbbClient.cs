using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina.Tests.Simulation;

/// <summary>A bare TCP client for tests: sends raw text, collects raw text and parsed messages, with timeouts.</summary>
internal sealed class RawAbbClient : IDisposable
{
    public static readonly TimeSpan Timeout = TimeSpan.FromSeconds(10);

    private readonly TcpClient _client = new();
    private readonly AbbMessageReader _reader = new();
    private readonly StringBuilder _raw = new();
    private readonly byte[] _bytes = new byte[4096];

    private RawAbbClient() { }

    public string RawText => _raw.ToString();

    public static async Task<RawAbbClient> ConnectAsync(int port)
    {
        var client = new RawAbbClient();
        using var cts = new CancellationTokenSource(Timeout);
        await client._client.ConnectAsync(IPAddress.Loopback, port, cts.Token);
        client._client.NoDelay = true;
        return client;
    }

    public Task SendAsync(string text) => _client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(text)).AsTask();

    /// <summary>Reads the five handshake messages of a 1.6 driver: version, pose, joints, external axes, progress.</summary>
    public Task<List<AbbMessage>> ReadHandshakeAsync() => ReadMessagesAsync(5);

    /// <summary>Reads until <paramref name="count"/> messages have arrived (throws on timeout).</summary>
    public async Task<List<AbbMessage>> ReadMessagesAsync(int count)
    {
        using var cts = new CancellationTokenSource(Timeout);
        var messages = new List<AbbMessage>();
        while (true)
        {
            while (messages.Count < count && _reader.TryRead(out var message))
            {
                messages.Add(message);
            }
            if (messages.Count == count)
            {
                return messages;
            }
            int n = await _client.GetStream().ReadAsync(_bytes, cts.Token);
            if (n == 0)
            {
                throw new IOException($"Connection closed after {messages.Count} of {count} messages.");
            }
            _raw.Append(Encoding.ASCII.GetString(_bytes, 0, n));
            _reader.Append(_bytes.AsSpan(0, n));
        }
    }

    /// <summary>Reads until the server closes the connection; returns the text received meanwhile.</summary>
    public async Task<string> ReadToEndAsync()
    {
        using var cts = new CancellationTokenSource(Timeout);
        var text = new StringBuilder();
        int n;
        while ((n = await _client.GetStream().ReadAsync(_bytes, cts.Token)) > 0)
        {
            text.Append(Encoding.ASCII.GetString(_bytes, 0, n));
        }
        return text.ToString();
    }

    public void Dispose() => _client.Dispose();

    /// <summary>Waits until <paramref name="condition"/> holds, checking every few milliseconds (throws on timeout).</summary>
    public static async Task WaitUntilAsync(Func<bool> condition, string what)
    {
        var deadline = DateTime.UtcNow + Timeout;
        while (!condition())
        {
            if (DateTime.UtcNow > deadline)
            {
                throw new TimeoutException("Timed out waiting until " + what);
            }
            await Task.Delay(5);
        }
    }
}
