using System.Net.WebSockets;
using System.Text;
using System.Threading.Channels;

namespace Machina.Bridge;

/// <summary>
/// One connected WebSocket client: its name and a queue of messages that one loop sends in order. Messages are queued
/// without waiting, so a slow client never slows the robot or the other clients; one that falls too far behind is dropped.
/// </summary>
internal sealed class BridgeClient
{
    private readonly WebSocket _socket;
    private readonly Channel<string> _outbox;
    private readonly Action<BridgeClient> _overflowed;
    private int _closing;
    private WebSocketCloseStatus _closeStatus = WebSocketCloseStatus.NormalClosure;
    private string _closeReason = "";

    internal BridgeClient(WebSocket socket, string user, int capacity, Action<BridgeClient> overflowed)
    {
        _socket = socket;
        User = user;
        _overflowed = overflowed;
        _outbox = Channel.CreateBounded<string>(new BoundedChannelOptions(capacity)
        {
            SingleReader = true,
            FullMode = BoundedChannelFullMode.Wait,
        });
    }

    /// <summary>The name the client gave in its URL (<c>?name=GH</c>), or its address when it gave none.</summary>
    internal string User { get; }

    /// <summary>True when the client asked for the arm's link positions (<c>?arm=1</c>): it then gets the <c>arm</c> messages too.</summary>
    internal bool WantsArm { get; init; }

    /// <summary>The client's WebSocket (received from by the connection's own loop).</summary>
    internal WebSocket Socket => _socket;

    /// <summary>Queues a message; when the queue is full the client is reported as too slow and nothing waits.</summary>
    internal void Send(string json)
    {
        if (!_outbox.Writer.TryWrite(json) && Volatile.Read(ref _closing) == 0)
        {
            _overflowed(this);
        }
    }

    /// <summary>Sends queued messages until <see cref="Close"/> is called, then starts the close handshake.</summary>
    internal async Task RunSendLoopAsync(CancellationToken cancellationToken)
    {
        byte[] buffer = new byte[4096];
        try
        {
            await foreach (string json in _outbox.Reader.ReadAllAsync(cancellationToken).ConfigureAwait(false))
            {
                int length = Encoding.UTF8.GetMaxByteCount(json.Length);
                if (length > buffer.Length)
                {
                    buffer = new byte[Math.Max(length, buffer.Length * 2)];
                }
                int count = Encoding.UTF8.GetBytes(json, buffer);
                await _socket.SendAsync(buffer.AsMemory(0, count), WebSocketMessageType.Text, true, cancellationToken).ConfigureAwait(false);
            }
            if (_socket.State is WebSocketState.Open or WebSocketState.CloseReceived)
            {
                await _socket.CloseOutputAsync(_closeStatus, _closeReason, cancellationToken).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is WebSocketException or IOException or OperationCanceledException or ObjectDisposedException)
        {
            // The client went away or the bridge is stopping: nothing more can be delivered.
        }
    }

    /// <summary>Stops accepting messages; the send loop delivers what is queued, then closes with this status.</summary>
    internal void Close(WebSocketCloseStatus status, string reason)
    {
        if (Interlocked.Exchange(ref _closing, 1) == 0)
        {
            _closeStatus = status;
            _closeReason = reason;
            _outbox.Writer.TryComplete();
        }
    }

    /// <summary>Drops the connection at once, without a close handshake.</summary>
    internal void Abort()
    {
        Interlocked.Exchange(ref _closing, 1);
        _outbox.Writer.TryComplete();
        _socket.Abort();
    }
}
