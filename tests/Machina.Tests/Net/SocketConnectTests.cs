using System.Net;
using System.Net.Sockets;

namespace Machina.Tests.Net;

/// <summary>
/// How a link connects when the peer does not answer at once (a listener whose queue is full): the connection is waited for
/// in <c>poll</c>, cancellably.
/// </summary>
public sealed class SocketConnectTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    [Fact]
    public async Task Connect_ToAListenerWhoseQueueIsFull_WaitsUntilItTakesTheConnection()
    {
        using FullListener full = await FullListener.OpenAsync();
        Socket listener = full.Listener;
        int port = full.Port;

        Task<TcpLink> connecting = TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None);
        using Socket taken = listener.Accept();   // room again: the SYN the system sends again is answered
        await using TcpLink link = await connecting.WaitAsync(Bound);
        using Socket server = listener.Accept();

        Assert.True(link.Socket.Connected);
        Assert.False(link.Socket.Blocking);
        Assert.Equal(((IPEndPoint)link.Socket.LocalEndPoint!).Port, ((IPEndPoint)server.RemoteEndPoint!).Port);
    }

    [Fact]
    public async Task Connect_ToAListenerWhoseQueueStaysFull_EndsWhenCancelled()
    {
        using FullListener full = await FullListener.OpenAsync();
        Socket listener = full.Listener;
        int port = full.Port;
        using var cancel = new CancellationTokenSource();

        Task<TcpLink> connecting = TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, cancel.Token);
        await cancel.CancelAsync();

        await Assert.ThrowsAnyAsync<OperationCanceledException>(() => connecting.WaitAsync(Bound));
    }

    /// <summary>
    /// A listener on loopback whose queue holds one connection not accepted yet (kept open until disposed): the system drops the
    /// next connection's SYN until there is room.
    /// </summary>
    private sealed class FullListener : IDisposable
    {
        private readonly Socket _first;

        private FullListener(Socket listener, Socket first)
        {
            Listener = listener;
            _first = first;
        }

        public Socket Listener { get; }

        public int Port => ((IPEndPoint)Listener.LocalEndPoint!).Port;

        public static async Task<FullListener> OpenAsync()
        {
            var listener = new Socket(SocketType.Stream, ProtocolType.Tcp);
            listener.Bind(new IPEndPoint(IPAddress.Loopback, 0));
            listener.Listen(0);
            var first = new Socket(SocketType.Stream, ProtocolType.Tcp);
            await first.ConnectAsync(IPAddress.Loopback, ((IPEndPoint)listener.LocalEndPoint!).Port).WaitAsync(Bound);
            return new FullListener(listener, first);
        }

        public void Dispose()
        {
            _first.Dispose();
            Listener.Dispose();
        }
    }
}
