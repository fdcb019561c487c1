using System.Net;
using System.Net.Sockets;
using System.Net.WebSockets;
using System.Text;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

/// <summary>Issue 28: no web site can move the robot (framing, token), and slow connections cannot lock clients out.</summary>
public class BridgeSecurityTests
{
    [Fact]
    public async Task Page_RefusesToBeFramed_AndSendsNoReferrer()
    {
        await using BridgeServer bridge = await StartAsync();
        string page = await RawHttp.RequestAsync(bridge.Port, $"GET /?run=MoveTo(333,111,444) HTTP/1.1\r\nHost: 127.0.0.1:{bridge.Port}\r\n\r\n");
        string head = page[..page.IndexOf("\r\n\r\n", StringComparison.Ordinal)];
        Assert.Contains("\r\nContent-Security-Policy: default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; connect-src 'self' ws: wss:; img-src data:; " +
            "frame-ancestors 'none'; form-action 'none'; base-uri 'none'\r\n", head + "\r\n", StringComparison.Ordinal);
        Assert.Contains("\r\nX-Frame-Options: DENY\r\n", head + "\r\n", StringComparison.Ordinal);
        Assert.Contains("\r\nReferrer-Policy: no-referrer\r\n", head + "\r\n", StringComparison.Ordinal);
        // The page's script never sends on its own: the only call to send() is the button's and Ctrl+Enter's.
        Assert.DoesNotContain("send();\n      }\n    };", page, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Token_ClientsWithoutIt_Refused403_WithIt_Served()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { Token = "s3cret-key" });
        const string key = "dGhlIHNhbXBsZSBub25jZQ==";
        string Handshake(string query) =>
            $"GET /Bridge{query} HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: {key}\r\n\r\n";
        string refused = RawHttp.Expected(403, "Forbidden", "This bridge needs its token: add authkey=TOKEN to the address, e.g. ws://HOST:PORT/Bridge?authkey=TOKEN.");
        Assert.Equal(refused, await RawHttp.RequestAsync(bridge.Port, Handshake("")));
        Assert.Equal(refused, await RawHttp.RequestAsync(bridge.Port, Handshake("?name=GH&authkey=s3cret-kez")));
        Assert.Equal(refused, await RawHttp.RequestAsync(bridge.Port, Handshake("?authkey=s3cret-key2")));
        Assert.Equal(refused, await RawHttp.RequestAsync(bridge.Port, Handshake("?authkey")));
        Assert.Equal("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=\r\n\r\n",
            await RawHttp.RequestAsync(bridge.Port, Handshake("?name=GH&authkey=s3cret-key"), untilBlankLine: true));

        await Assert.ThrowsAsync<WebSocketException>(() => TestClient.ConnectAsync(bridge, "?name=GH"));
        await using TestClient client = await TestClient.ConnectAsync(bridge, "?name=GH&authkey=s3cret-key");
        await client.SendAsync("SpeedTo(33);");
        await client.ReceiveUntilAsync(e => e.Event() == "action-issued" && e.GetProperty("last").GetString() == "SpeedTo(33);");
    }

    [Fact]
    public void Token_RequiredBeyondLoopback_AndWritableInAnAddress()
    {
        var open = Assert.Throws<ArgumentException>(() => new BridgeServer(new BridgeOptions { Listen = new IPEndPoint(IPAddress.Any, 0) }));
        Assert.Equal("Token", open.ParamName);
        Assert.StartsWith("Listening on 0.0.0.0 lets other computers connect, so a token is required", open.Message, StringComparison.Ordinal);
        foreach (string bad in new[] { "short", "has space", "a&b=cdefgh", "abcdefgh#", "ünïcödé-key" })
        {
            Assert.Equal("Token", Assert.Throws<ArgumentException>(() => new BridgeServer(new BridgeOptions { Token = bad })).ParamName);
        }
        Assert.Equal("MaxPendingHandshakes", Assert.ThrowsAny<ArgumentException>(() => new BridgeServer(new BridgeOptions { MaxPendingHandshakes = 0 })).ParamName);
        _ = new BridgeServer(new BridgeOptions { Listen = new IPEndPoint(IPAddress.Any, 0), Token = "long-enough" }); // accepted
    }

    [Fact]
    public async Task HalfOpenConnections_DoNotTakeClientSlots_ClientsStillConnect()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { MaxConnections = 2, RequestTimeout = TimeSpan.FromMinutes(5) });
        var idle = new List<TcpClient>();
        try
        {
            for (int i = 0; i < 300; i++)
            {
                var tcp = new TcpClient();
                idle.Add(tcp);
                using var timeout = new CancellationTokenSource(Limit);
                await tcp.ConnectAsync(IPAddress.Loopback, bridge.Port, timeout.Token);
                if (i % 2 == 0)
                {
                    await tcp.GetStream().WriteAsync(Encoding.ASCII.GetBytes("GET /Bridge HTTP/1.1\r\nHost: x\r\n"), timeout.Token); // and never the blank line
                }
            }
            // The handshakes of the idle connections would last minutes; the clients are served at once, up to the client limit.
            await using TestClient a = await TestClient.ConnectAsync(bridge, "?name=A");
            await using TestClient b = await TestClient.ConnectAsync(bridge, "?name=B");
            var full = await Assert.ThrowsAsync<WebSocketException>(() => TestClient.ConnectAsync(bridge, "?name=C"));
            Assert.Contains("503", full.Message, StringComparison.Ordinal);
            await a.SendAsync("SpeedTo(44);");
            await a.ReceiveUntilAsync(e => e.Event() == "action-issued" && e.GetProperty("last").GetString() == "SpeedTo(44);");
        }
        finally
        {
            idle.ForEach(t => t.Dispose());
        }
    }

    [Fact]
    public async Task PendingHandshakes_OverTheLimit_TheOldestIsDropped()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { MaxPendingHandshakes = 4, RequestTimeout = TimeSpan.FromMinutes(5) });
        using var oldest = new TcpClient();
        await oldest.ConnectAsync(IPAddress.Loopback, bridge.Port).WaitAsync(Limit);
        await EventuallyAsync(() => bridge.PendingHandshakeCount == 1, "the first connection is in its handshake");
        var others = new List<TcpClient>();
        try
        {
            for (int i = 0; i < 4; i++)
            {
                var tcp = new TcpClient();
                others.Add(tcp);
                await tcp.ConnectAsync(IPAddress.Loopback, bridge.Port).WaitAsync(Limit);
            }
            Assert.Equal(RawHttp.Expected(503, "Service Unavailable", "Too many connections are opening at once; try again."), await RawHttp.ReadAllAsync(oldest.GetStream()));
            await EventuallyAsync(() => bridge.PendingHandshakeCount == 4, "four connections are in their handshake");
        }
        finally
        {
            others.ForEach(t => t.Dispose());
        }
    }

    [Fact]
    public async Task Handshake_TrickledPastTheDeadline_408()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { RequestTimeout = TimeSpan.FromMilliseconds(300) });
        using var tcp = new TcpClient();
        await tcp.ConnectAsync(IPAddress.Loopback, bridge.Port).WaitAsync(Limit);
        NetworkStream stream = tcp.GetStream();
        Task<string> answer = RawHttp.ReadAllAsync(stream);
        // One byte at a time keeps the connection busy, but the deadline is for the whole head.
        foreach (char c in "GET / HTTP/1.1\r\nHost: x\r\n")
        {
            if (answer.IsCompleted)
            {
                break;
            }
            try
            {
                await stream.WriteAsync(new[] { (byte)c }).AsTask().WaitAsync(Limit);
            }
            catch (IOException)
            {
                break; // closed after the answer
            }
            await Task.Delay(50);
        }
        Assert.Equal(RawHttp.Expected(408, "Request Timeout", "The request did not arrive in time."), await answer.WaitAsync(Limit));
    }

    [Fact]
    public async Task ActionFailed_EveryClientGetsTheActionFailedEvent()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient a = await TestClient.ConnectAsync(bridge, "?name=A");
        await using TestClient b = await TestClient.ConnectAsync(bridge, "?name=B");
        await EventuallyAsync(() => bridge.ClientCount == 2, "both clients are registered");
        var action = new ActionTranslation(new Vector(5000, 0, 0), false);
        var failure = new ActionFailedException(action, "Position outside reach", "50050");
        var args = new ActionFailedArgs(failure, bridge.Robot.GetExecutedState());
        ((IOnlineHost)bridge.Robot).Raise(args);
        foreach (TestClient c in new[] { a, b })
        {
            var e = await c.ReceiveAsync();
            Assert.Equal(args.ToJsonString(), e.GetRawText());
            Assert.Equal("action-failed", e.Event());
            Assert.Equal("Position outside reach", e.GetProperty("error").GetString());
            Assert.Equal("50050", e.GetProperty("code").GetString());
        }
    }
}

/// <summary>Raw HTTP over loopback, for answers checked byte for byte.</summary>
internal static class RawHttp
{
    /// <summary>The bridge's plain-text error answer, written out here independently of the server's code.</summary>
    internal static string Expected(int status, string reason, string message)
    {
        string body = message + "\n";
        return $"HTTP/1.1 {status} {reason}\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: {Encoding.UTF8.GetByteCount(body)}\r\n" +
            $"Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n{body}";
    }

    /// <summary>Sends raw bytes and reads the answer until the server closes (or, for a handshake, until the blank line).</summary>
    internal static async Task<string> RequestAsync(int port, string request, bool untilBlankLine = false)
    {
        using var tcp = new TcpClient();
        using var timeout = new CancellationTokenSource(BridgeTestSupport.Limit);
        await tcp.ConnectAsync(IPAddress.Loopback, port, timeout.Token);
        NetworkStream stream = tcp.GetStream();
        await stream.WriteAsync(Encoding.Latin1.GetBytes(request), timeout.Token);
        return await ReadAllAsync(stream, untilBlankLine, timeout.Token);
    }

    /// <summary>
    /// Reads until the server closes (or until the blank line), at most <see cref="BridgeTestSupport.Limit"/>, or until
    /// <paramref name="deadline"/> when the caller's request has one.
    /// </summary>
    internal static async Task<string> ReadAllAsync(NetworkStream stream, bool untilBlankLine = false, CancellationToken deadline = default)
    {
        using var timeout = deadline.CanBeCanceled ? CancellationTokenSource.CreateLinkedTokenSource(deadline) : new CancellationTokenSource(BridgeTestSupport.Limit);
        var answer = new MemoryStream();
        var buffer = new byte[4096];
        while (true)
        {
            int n;
            try
            {
                n = await stream.ReadAsync(buffer, timeout.Token);
            }
            catch (IOException)
            {
                break; // reset after the answer
            }
            if (n == 0)
            {
                break;
            }
            answer.Write(buffer, 0, n);
            if (untilBlankLine && Encoding.Latin1.GetString(answer.ToArray()).Contains("\r\n\r\n", StringComparison.Ordinal))
            {
                break;
            }
        }
        return Encoding.Latin1.GetString(answer.ToArray());
    }
}
