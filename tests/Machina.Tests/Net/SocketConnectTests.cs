using System.Net;
using System.Net.Sockets;
using System.Runtime.ExceptionServices;

namespace Machina.Tests.Net;

/// <summary>
/// How a link connects: where the peer answers at once (a controller on the network, a twin on this computer) the connection
/// is made by one blocking <c>connect</c> bounded by the socket's send timeout (Linux), without the <c>EINPROGRESS</c>
/// <see cref="SocketException"/> that a non-blocking connect throws every time; a peer that does not answer at once is
/// still waited for in <c>poll</c>, cancellably.
/// </summary>
public sealed class SocketConnectTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    /// <summary>Marks the exceptions of this test's own threads (a thread it starts inherits the marker with the execution context).</summary>
    private static readonly AsyncLocal<string?> Owner = new();

    [Fact]
    public async Task Connect_ToAListenerThatAnswers_ThrowsNothing_AndGivesANonBlockingConnectedSocket()
    {
        if (!OperatingSystem.IsLinux())
        {
            return; // elsewhere a blocking connect is bounded by the system's timeout only: the non-blocking connect stays
        }
        using var listener = new Socket(SocketType.Stream, ProtocolType.Tcp);
        listener.Bind(new IPEndPoint(IPAddress.Loopback, 0));
        listener.Listen(8);
        int port = ((IPEndPoint)listener.LocalEndPoint!).Port;
        string me = Guid.NewGuid().ToString("N");
        Owner.Value = me;
        var thrown = new List<string>();
        void Record(object? sender, FirstChanceExceptionEventArgs e)
        {
            if (Owner.Value == me)
            {
                lock (thrown)
                {
                    thrown.Add($"{e.Exception.GetType().Name}: {e.Exception.Message}");
                }
            }
        }

        TcpLink link;
        AppDomain.CurrentDomain.FirstChanceException += Record;
        try
        {
            link = await TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None);
        }
        finally
        {
            AppDomain.CurrentDomain.FirstChanceException -= Record;
        }

        await using (link)
        {
            Assert.Empty(thrown);
            Assert.True(link.Socket.Connected);
            Assert.False(link.Socket.Blocking);
            Assert.True(link.Socket.NoDelay);
            Assert.Equal(0, link.Socket.SendTimeout);
            using Socket server = listener.Accept();
            link.Post("hi"u8);
            byte[] buffer = new byte[2];
            using var timeout = new CancellationTokenSource(Bound);
            Assert.Equal(2, await server.ReceiveAsync(buffer, SocketFlags.None, timeout.Token));
            Assert.Equal("hi"u8.ToArray(), buffer);
        }
    }

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
