using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Tests.Support;

namespace Machina.Tests.Net;

/// <summary>
/// The TCP link under the drivers: what the receive loop's handler posts (the requests an acknowledgement releases) goes out
/// in one write when the read is handled, in order with what other threads post, and nothing is lost however much it is.
/// </summary>
public sealed class TcpLinkTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    [Fact]
    public async Task Post_FromTheReceiveHandler_IsWrittenInOneCallWhenTheReadIsHandled()
    {
        await using var pair = await LinkPair.OpenAsync(new PostingReceiver("one\n", "two\n", "three\n"));
        await pair.Server.SendAsync(Encoding.ASCII.GetBytes("go"));

        string received = await pair.ReadAsync("one\ntwo\nthree\n".Length);

        Assert.Equal("one\ntwo\nthree\n", received);
        Assert.Equal(1, pair.Link.SocketWrites);
    }

    [Fact]
    public async Task Post_FromAnotherThread_IsWrittenAtOnceEachTime()
    {
        await using var pair = await LinkPair.OpenAsync(new PostingReceiver());

        foreach (string text in new[] { "a\n", "b\n", "c\n" })
        {
            pair.Link.Post(Encoding.ASCII.GetBytes(text));
        }
        string received = await pair.ReadAsync(6);

        Assert.Equal("a\nb\nc\n", received);
        Assert.Equal(3, pair.Link.SocketWrites);
    }

    [Fact]
    public async Task Post_MoreThanTheSocketTakesFromTheHandler_ArrivesWholeAndInOrder()
    {
        const int chunks = 64, chunkSize = 64 * 1024;
        string[] posts = [.. Enumerable.Range(0, chunks).Select(i => new string((char)('A' + (i % 26)), chunkSize))];
        await using var pair = await LinkPair.OpenAsync(new PostingReceiver(posts));
        await pair.Server.SendAsync(Encoding.ASCII.GetBytes("go"));

        Task<string> reading = pair.ReadAsync(chunks * chunkSize + 4);
        await pair.Receiver.Posted.Task.WaitAsync(Bound);
        pair.Link.Post(Encoding.ASCII.GetBytes("end\n"));
        string received = await reading;

        Assert.Equal(string.Concat(posts) + "end\n", received);
        // The send loop waited for room with poll: an asynchronous send would have left the socket registered with the
        // runtime's socket engine, and every later acknowledgement would wake it.
        Assert.False(OperatingSystem.IsLinux() && SocketEngine.Watches(pair.Link.Socket), "the link's socket is registered with the runtime's epoll");
    }

    [Fact]
    public async Task Post_FromAnotherThreadWhileTheHandlerHolds_KeepsTheOrderOfPosting()
    {
        var receiver = new HandshakeReceiver();
        await using var pair = await LinkPair.OpenAsync(receiver);
        await pair.Server.SendAsync(Encoding.ASCII.GetBytes("go"));

        await receiver.FirstPosted.Task.WaitAsync(Bound);
        pair.Link.Post(Encoding.ASCII.GetBytes("second\n"));
        receiver.MayGoOn.SetResult();
        string received = await pair.ReadAsync("first\nsecond\nthird\n".Length);

        Assert.Equal("first\nsecond\nthird\n", received);
    }

    [Fact]
    public async Task TheLinksSocket_IsNotWatchedByTheRuntimesSocketEngine()
    {
        if (!OperatingSystem.IsLinux())
        {
            return; // the kernel lists what an epoll instance watches in /proc on Linux only
        }
        var receiver = new PostingReceiver("ack\n");
        await using var pair = await LinkPair.OpenAsync(receiver);
        byte[] reply = new byte[4];
        // Nothing has arrived yet, so this receive waits: the engine watches the server's socket from now on.
        Task<int> replying = pair.Server.ReceiveAsync(reply, SocketFlags.None);
        await pair.Server.SendAsync(Encoding.ASCII.GetBytes("go"));
        Assert.Equal(4, await replying.WaitAsync(Bound));
        Assert.Equal("ack\n", Encoding.ASCII.GetString(reply));

        // Watched, every arrival (an acknowledgement) would wake the engine's thread and a thread-pool worker, although the
        // link reads with poll on a thread of its own.
        Assert.False(SocketEngine.Watches(pair.Link.Socket), "the link's socket is registered with the runtime's epoll");
        Assert.True(SocketEngine.Watches(pair.Server), "the check sees a socket that was read asynchronously");
    }

    [Fact]
    public async Task Connect_ToAPortNobodyListensOn_SaysTheConnectionWasRefused()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();

        var e = await Assert.ThrowsAsync<RobotConnectionException>(
            () => TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None));

        Assert.Equal($"Could not connect to 127.0.0.1:{port}: Connection refused. Is the driver running there?", e.Message);
    }

    [Fact]
    public async Task Start_WithoutAName_ReadsOnTheMachinaLinkThread()
    {
        Assert.Equal("Machina link", await ReaderThreadNameAsync(null));
    }

    [Fact]
    public async Task Start_AsASideLink_ReadsOnTheMachinaSideThread()
    {
        // A side link (a monitor, UR's RTDE or script port) is told apart from the driver's link in a per-thread reading.
        Assert.Equal("Machina side", await ReaderThreadNameAsync(TcpLink.SideThreadName));
    }

    /// <summary>The name of the thread that handles a byte sent to a link started with <paramref name="name"/> (the default when null).</summary>
    private static async Task<string?> ReaderThreadNameAsync(string? name)
    {
        var receiver = new NamingReceiver();
        await using var pair = await LinkPair.OpenAsync(receiver, name);
        await pair.Server.SendAsync(new byte[] { 1 });
        return await receiver.ThreadName.Task.WaitAsync(Bound);
    }

    [Fact]
    public async Task Connect_ByName_ReachesTheListener()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Task<Socket> accepting = listener.AcceptSocketAsync();
            await using TcpLink link = await TcpLink.ConnectAsync("localhost", port, Bound, TimeProvider.System, CancellationToken.None);
            using Socket server = await accepting.WaitAsync(Bound);

            Assert.Equal($"localhost:{port}", link.RemoteAddress);
            Assert.True(link.LocalAddress is { } local && IPAddress.IsLoopback(local.IsIPv4MappedToIPv6 ? local.MapToIPv4() : local));
        }
        finally
        {
            listener.Stop();
        }
    }

    [Fact]
    public async Task AHandlerThatThrows_EndsTheLink_AndItsReceiverHearsWhy()
    {
        var receiver = new ThrowingReceiver();
        await using var pair = await LinkPair.OpenAsync(receiver);
        await pair.Server.SendAsync(Encoding.ASCII.GetBytes("go"));

        Exception? error = await receiver.Closed.Task.WaitAsync(Bound);

        Assert.IsType<InvalidOperationException>(error);
        Assert.Equal("the handler failed", error!.Message);
    }

    /// <summary>Throws on its first read, as a driver's codec with a bug would, and keeps what the link reports then.</summary>
    private sealed class ThrowingReceiver : ILinkReceiver
    {
        public TaskCompletionSource<Exception?> Closed { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void OnReceived(ReadOnlySpan<byte> data) => throw new InvalidOperationException("the handler failed");

        public void OnClosed(Exception? error) => Closed.TrySetResult(error);
    }

    /// <summary>On its first read, posts each text in turn (from the receive loop's thread), then reports that it did.</summary>
    private sealed class NamingReceiver : ILinkReceiver
    {
        public TaskCompletionSource<string?> ThreadName { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void OnReceived(ReadOnlySpan<byte> data) => ThreadName.TrySetResult(Thread.CurrentThread.Name);

        public void OnClosed(Exception? error) => ThreadName.TrySetResult("closed");
    }

    internal sealed class PostingReceiver(params string[] texts) : ILinkReceiver
    {
        private int _reads;

        public TcpLink? Link { get; set; }

        public TaskCompletionSource Posted { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (Interlocked.Increment(ref _reads) == 1)
            {
                foreach (string text in texts)
                {
                    Link!.Post(Encoding.ASCII.GetBytes(text));
                }
                Posted.SetResult();
            }
        }

        public void OnClosed(Exception? error)
        {
        }
    }

    /// <summary>Posts "first", lets the test post from its thread, then posts "third" before the read is handled.</summary>
    private sealed class HandshakeReceiver : ILinkReceiver
    {
        private int _reads;

        public TcpLink? Link { get; set; }

        public TaskCompletionSource FirstPosted { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public TaskCompletionSource MayGoOn { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (Interlocked.Increment(ref _reads) == 1)
            {
                Link!.Post(Encoding.ASCII.GetBytes("first\n"));
                FirstPosted.SetResult();
                MayGoOn.Task.Wait(Bound);
                Link.Post(Encoding.ASCII.GetBytes("third\n"));
            }
        }

        public void OnClosed(Exception? error)
        {
        }
    }

    /// <summary>A listening socket on loopback (port 0), a link connected to it, and the accepted server end.</summary>
    internal sealed class LinkPair : IAsyncDisposable
    {
        private readonly TcpListener _listener;

        private LinkPair(TcpListener listener, TcpLink link, Socket server, ILinkReceiver receiver)
        {
            _listener = listener;
            Link = link;
            Server = server;
            Receiver = receiver as PostingReceiver ?? new PostingReceiver();
        }

        public TcpLink Link { get; }

        public Socket Server { get; }

        public PostingReceiver Receiver { get; }

        public static async Task<LinkPair> OpenAsync(ILinkReceiver receiver, string? threadName = null)
        {
            var listener = new TcpListener(IPAddress.Loopback, 0);
            listener.Start();
            int port = ((IPEndPoint)listener.LocalEndpoint).Port;
            Task<Socket> accepting = listener.AcceptSocketAsync();
            TcpLink link = await TcpLink.ConnectAsync("127.0.0.1", port, Bound, TimeProvider.System, CancellationToken.None);
            Socket server = await accepting.WaitAsync(Bound);
            switch (receiver)
            {
                case PostingReceiver p:
                    p.Link = link;
                    break;
                case HandshakeReceiver h:
                    h.Link = link;
                    break;
            }
            if (threadName is null)
            {
                link.Start(receiver);
            }
            else
            {
                link.Start(receiver, threadName);
            }
            return new LinkPair(listener, link, server, receiver);
        }

        /// <summary>Reads exactly <paramref name="length"/> bytes from the server end, within the bound.</summary>
        public async Task<string> ReadAsync(int length)
        {
            using var timeout = new CancellationTokenSource(Bound);
            byte[] buffer = new byte[length];
            int read = 0;
            while (read < length)
            {
                int n = await Server.ReceiveAsync(buffer.AsMemory(read), SocketFlags.None, timeout.Token);
                Assert.True(n > 0, $"The link closed after {read} of {length} bytes.");
                read += n;
            }
            return Encoding.ASCII.GetString(buffer);
        }

        public async ValueTask DisposeAsync()
        {
            await Link.DisposeAsync();
            Server.Dispose();
            _listener.Stop();
        }
    }
}
