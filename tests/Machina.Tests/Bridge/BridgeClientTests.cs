using System.Net.WebSockets;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

public class BridgeClientTests
{
    [Fact]
    public async Task Send_ClientStopsReading_QueueFullReportedOnceAndTheClientDropped()
    {
        var stream = new StalledStream();
        using WebSocket socket = WebSocket.CreateFromStream(stream, new WebSocketCreationOptions { IsServer = true });
        int overflows = 0;
        var client = new BridgeClient(socket, "slow", 16, c =>
        {
            Interlocked.Increment(ref overflows);
            c.Abort();
        });
        Task sending = Task.Run(() => client.RunSendLoopAsync(CancellationToken.None));

        for (int i = 0; i < 100; i++)
        {
            client.Send("{\"event\":\"action-issued\"}"); // never waits, even though nothing can be written
        }

        await sending.WaitAsync(Limit); // the abort ended the stalled write
        Assert.Equal(1, overflows);
        Assert.Equal(WebSocketState.Aborted, socket.State);
        Assert.InRange(stream.Writes, 0, 1);
    }

    /// <summary>A connection whose peer never reads: every write waits until the stream is disposed.</summary>
    private sealed class StalledStream : Stream
    {
        private readonly TaskCompletionSource _disposed = new(TaskCreationOptions.RunContinuationsAsynchronously);
        private int _writes;

        internal int Writes => Volatile.Read(ref _writes);

        public override bool CanRead => true;
        public override bool CanSeek => false;
        public override bool CanWrite => true;
        public override long Length => throw new NotSupportedException();
        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public override async ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            Interlocked.Increment(ref _writes);
            await _disposed.Task.WaitAsync(cancellationToken);
            throw new ObjectDisposedException(nameof(StalledStream));
        }

        public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            await _disposed.Task.WaitAsync(cancellationToken);
            return 0;
        }

        protected override void Dispose(bool disposing)
        {
            _disposed.TrySetResult();
            base.Dispose(disposing);
        }

        public override void Flush() { }
        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
    }
}
