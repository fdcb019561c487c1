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
        await using var pair = await StartedPair.OpenAsync();

        AppDomain.CurrentDomain.FirstChanceException += Record;
        try
        {
            pair.Link.CloseSocket();
            await pair.Link.DisposeAsync();
        }
        finally
        {
            AppDomain.CurrentDomain.FirstChanceException -= Record;
        }

        Assert.Empty(thrown);
        using var timeout = new CancellationTokenSource(Bound);
        Assert.Equal(0, await pair.Server.ReceiveAsync(new byte[1], SocketFlags.None, timeout.Token));
    }

    [Fact]
    public async Task CloseSocket_WhileTheLoopWaits_EndsTheLoopAndTellsTheReceiverItWasClosedHere()
    {
        await using var pair = await StartedPair.OpenAsync();

        pair.Link.CloseSocket();
        Exception? error = await pair.Receiver.Closed.Task.WaitAsync(Bound);

        Assert.IsType<ObjectDisposedException>(error);
    }

    /// <summary>A started link on loopback (<see cref="TcpLinkTests.LinkPair"/>) and what its receiver heard at its close.</summary>
    private sealed class StartedPair : IAsyncDisposable
    {
        private readonly TcpLinkTests.LinkPair _pair;

        private StartedPair(TcpLinkTests.LinkPair pair, ClosingReceiver receiver)
        {
            _pair = pair;
            Receiver = receiver;
        }

        public TcpLink Link => _pair.Link;

        public Socket Server => _pair.Server;

        public ClosingReceiver Receiver { get; }

        public static async Task<StartedPair> OpenAsync()
        {
            var receiver = new ClosingReceiver();
            return new StartedPair(await TcpLinkTests.LinkPair.OpenAsync(receiver), receiver);
        }

        public ValueTask DisposeAsync() => _pair.DisposeAsync();
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
