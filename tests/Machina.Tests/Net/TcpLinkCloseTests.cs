using System.Net;
using System.Net.Sockets;

namespace Machina.Tests.Net;

/// <summary>
/// Closing a link: a driver closes its links' sockets, then disposes the links (which close them again). Each disconnect of a
/// streamed program did that, and threw an <see cref="ObjectDisposedException"/> for the second shutdown and another in the
/// receive loop's next call on the disposed socket: exceptions caught at once, but paid (and their code compiled) per disconnect.
/// </summary>
public sealed class TcpLinkCloseTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    /// <summary>Marks the exceptions of this test's own threads (the link's loop threads inherit it with the execution context).</summary>
    private static readonly AsyncLocal<string?> Owner = new();

    [Fact]
    public async Task CloseSocketThenDispose_ThrowsNothing_AndThePeerSeesTheEnd()
    {
        string me = Guid.NewGuid().ToString("N");
        Owner.Value = me;
        var thrown = new List<string>();
        void Record(object? sender, System.Runtime.ExceptionServices.FirstChanceExceptionEventArgs e)
        {
            if (Owner.Value == me)
            {
                lock (thrown)
                {
                    thrown.Add($"{e.Exception.GetType().Name}: {e.Exception.Message}");
                }
            }
        }

        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Task<Socket> accepting = listener.AcceptSocketAsync();
            TcpLink link = await TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None);
            using Socket server = await accepting.WaitAsync(Bound);
            var receiver = new ClosingReceiver();
            link.Start(receiver);

            AppDomain.CurrentDomain.FirstChanceException += Record;
            try
            {
                link.CloseSocket();
                await link.DisposeAsync();
            }
            finally
            {
                AppDomain.CurrentDomain.FirstChanceException -= Record;
            }

            Assert.Empty(thrown);
            using var timeout = new CancellationTokenSource(Bound);
            int n = await server.ReceiveAsync(new byte[1], SocketFlags.None, timeout.Token);
            Assert.Equal(0, n);
        }
        finally
        {
            listener.Stop();
        }
    }

    [Fact]
    public async Task CloseSocket_WhileTheLoopWaits_EndsTheLoopAndTellsTheReceiverItWasClosedHere()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Task<Socket> accepting = listener.AcceptSocketAsync();
            TcpLink link = await TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None);
            using Socket server = await accepting.WaitAsync(Bound);
            var receiver = new ClosingReceiver();
            link.Start(receiver);

            link.CloseSocket();
            Exception? error = await receiver.Closed.Task.WaitAsync(Bound);
            await link.DisposeAsync();

            Assert.IsType<ObjectDisposedException>(error);
        }
        finally
        {
            listener.Stop();
        }
    }

    private sealed class ClosingReceiver : ILinkReceiver
    {
        public TaskCompletionSource<Exception?> Closed { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void OnReceived(ReadOnlySpan<byte> data)
        {
        }

        public void OnClosed(Exception? error) => Closed.TrySetResult(error);
    }
}
