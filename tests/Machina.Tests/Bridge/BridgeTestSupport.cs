using System.Net;
using System.Net.WebSockets;
using System.Text;
using System.Text.Json;
using System.Threading.Channels;
using Machina.Bridge;
using Machina.Tests.Support;

namespace Machina.Tests.Bridge;

/// <summary>Starts bridges on loopback with an OS-chosen port and a fast virtual controller, with bounded waits only.</summary>
internal static class BridgeTestSupport
{
    internal static readonly TimeSpan Limit = TimeSpan.FromSeconds(30);

    /// <summary>The Hello Robot program of the paper and of the spec's conformance transcripts.</summary>
    internal static readonly string[] HelloRobot =
    [
        "Message(\"Hello Robot!\");", "SpeedTo(100);", "MoveTo(400,300,500);", "Rotate(0,1,0,-90);", "Move(0,0,250);", "Wait(2000);", "AxesTo(0,0,0,0,90,0);",
    ];

    internal static BridgeOptions Options(Func<BridgeOptions, BridgeOptions>? change = null)
    {
        var options = new BridgeOptions
        {
            Listen = new IPEndPoint(IPAddress.Loopback, 0),
            SimulationSpeed = 50,
            RobotFactory = () =>
            {
                var robot = Robot.Create("Bridge", RobotType.ABB);
                robot.ConnectTimeout = Limit; // a loaded machine may be slow to accept; no test is about this timeout
                return robot;
            },
        };
        return change is null ? options : change(options);
    }

    internal static async Task<BridgeServer> StartAsync(Func<BridgeOptions, BridgeOptions>? change = null)
    {
        var bridge = new BridgeServer(Options(change));
        await bridge.StartAsync().WaitAsync(Limit);
        return bridge;
    }

    /// <summary>Waits for a condition that another thread makes true, at most <see cref="Limit"/>.</summary>
    internal static Task EventuallyAsync(Func<bool> condition, string what) => Eventually.TrueAsync(condition, what, Limit);
}

/// <summary>A WebSocket client like the original ones: it sends text and reads every message the bridge sends, in order.</summary>
internal sealed class TestClient : IAsyncDisposable
{
    private readonly ClientWebSocket _socket;
    private readonly Channel<string> _received = Channel.CreateUnbounded<string>();
    private readonly Task _pump;

    private TestClient(ClientWebSocket socket)
    {
        _socket = socket;
        _pump = Task.Run(PumpAsync);
    }

    internal WebSocketCloseStatus? CloseStatus => _socket.CloseStatus;

    internal static async Task<TestClient> ConnectAsync(BridgeServer bridge, string query = "?name=GH&client=Grasshopper", Action<ClientWebSocketOptions>? configure = null)
    {
        var socket = new ClientWebSocket();
        configure?.Invoke(socket.Options);
        using var timeout = new CancellationTokenSource(BridgeTestSupport.Limit);
        await socket.ConnectAsync(new Uri(bridge.WebSocketUri + query), timeout.Token);
        return new TestClient(socket);
    }

    private async Task PumpAsync()
    {
        var buffer = new byte[64 * 1024];
        var message = new MemoryStream();
        try
        {
            while (true)
            {
                var result = await _socket.ReceiveAsync(buffer, CancellationToken.None);
                if (result.MessageType == WebSocketMessageType.Close)
                {
                    if (_socket.State == WebSocketState.CloseReceived)
                    {
                        await _socket.CloseOutputAsync(WebSocketCloseStatus.NormalClosure, "", CancellationToken.None);
                    }
                    break;
                }
                message.Write(buffer, 0, result.Count);
                if (result.EndOfMessage)
                {
                    _received.Writer.TryWrite(Encoding.UTF8.GetString(message.ToArray()));
                    message.SetLength(0);
                }
            }
        }
        catch (Exception e) when (e is WebSocketException or ObjectDisposedException or OperationCanceledException)
        {
        }
        finally
        {
            _received.Writer.TryComplete();
        }
    }

    internal Task SendAsync(string text) => SendAsync(Encoding.UTF8.GetBytes(text), WebSocketMessageType.Text);

    internal async Task SendAsync(byte[] bytes, WebSocketMessageType type)
    {
        using var timeout = new CancellationTokenSource(BridgeTestSupport.Limit);
        await _socket.SendAsync(bytes, type, true, timeout.Token);
    }

    /// <summary>The next message's text; fails when none comes in time, or null when the bridge closed the connection.</summary>
    internal async Task<string?> ReceiveTextAsync()
    {
        using var timeout = new CancellationTokenSource(BridgeTestSupport.Limit);
        try
        {
            return await _received.Reader.ReadAsync(timeout.Token);
        }
        catch (ChannelClosedException)
        {
            return null;
        }
        catch (OperationCanceledException)
        {
            Assert.Fail("No message from the bridge in time.");
            throw;
        }
    }

    /// <summary>The next message that is not a motion update, parsed.</summary>
    internal async Task<JsonElement> ReceiveAsync()
    {
        while (true)
        {
            string text = await ReceiveTextAsync() ?? throw new InvalidOperationException("The bridge closed the connection.");
            JsonElement e = JsonDocument.Parse(text).RootElement.Clone();
            if (e.GetProperty("event").GetString() != "motion-update")
            {
                return e;
            }
        }
    }

    /// <summary>Messages (motion updates left out) up to and including the first one <paramref name="last"/> accepts.</summary>
    internal async Task<List<JsonElement>> ReceiveUntilAsync(Func<JsonElement, bool> last)
    {
        var messages = new List<JsonElement>();
        while (true)
        {
            JsonElement e = await ReceiveAsync();
            messages.Add(e);
            if (last(e))
            {
                return messages;
            }
        }
    }

    /// <summary>True when a message (motion updates aside) is already waiting.</summary>
    internal bool HasPendingMessage()
    {
        while (_received.Reader.TryPeek(out string? text))
        {
            if (!text.Contains("\"motion-update\"", StringComparison.Ordinal))
            {
                return true;
            }
            _received.Reader.TryRead(out _);
        }
        return false;
    }

    internal async Task CloseAsync()
    {
        using var timeout = new CancellationTokenSource(BridgeTestSupport.Limit);
        if (_socket.State == WebSocketState.Open)
        {
            // Only the pump receives: it reads the bridge's answering close frame.
            await _socket.CloseOutputAsync(WebSocketCloseStatus.NormalClosure, "bye", timeout.Token);
        }
        await _pump.WaitAsync(BridgeTestSupport.Limit);
    }

    public async ValueTask DisposeAsync()
    {
        _socket.Abort();
        await _pump.WaitAsync(BridgeTestSupport.Limit);
        _socket.Dispose();
    }
}

/// <summary>Reading fields of the bridge's JSON messages.</summary>
internal static class Json
{
    internal static string Event(this JsonElement e) => e.GetProperty("event").GetString()!;

    internal static int Id(this JsonElement e) => e.GetProperty("id").GetInt32();

    /// <summary>A field's JSON text exactly as sent, e.g. <c>[400,300,500]</c> or <c>null</c>.</summary>
    internal static string Raw(this JsonElement e, string name) => e.GetProperty(name).GetRawText();

    internal static string[] Keys(this JsonElement e) => [.. e.EnumerateObject().Select(p => p.Name)];
}
