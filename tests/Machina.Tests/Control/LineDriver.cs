using System.Collections.Concurrent;
using System.Text;

namespace Machina.Tests.Control;

/// <summary>
/// The smallest brand on the shared driver seam: a protocol of text lines. "hello V" is the handshake (version V),
/// "ack N" acknowledges N, "pose X" is a live pose on the monitor link; a line with '!' is garbage. It shows what a brand
/// supplies (a reader, what each message means, how it connects) and lets the tests drive the seam without a network.
/// </summary>
internal sealed class LineDriver(RobotLogger log, TimeProvider time, string? monitorHost = null, int monitorPort = 0)
    : DeviceDriver<string>(log, time, new LineReader(), "test controller"), IDeviceDriver
{
    internal const string Silence = "The test controller did not say hello.";

    /// <summary>Lines this driver handled on its driver link, in order.</summary>
    internal ConcurrentQueue<string> Handled { get; } = new();

    internal bool HasMonitor { get; private set; }

    protected override async Task<DeviceHandshake> OpenAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        DeviceHandshake handshake = await HandshakeAsync(timeout, () => Silence, cancellationToken);
        if (monitorHost is not null)
        {
            HasMonitor = await OpenMonitorAsync(monitorHost, monitorPort, new LineReader(), "No monitor here.", cancellationToken) is not null;
        }
        return handshake;
    }

    protected override void OnMessage(in string line)
    {
        Handled.Enqueue(line);
        if (line.StartsWith("hello ", StringComparison.Ordinal))
        {
            Handshake(new DeviceHandshake(line[6..], null, null, null, null));
        }
        else if (line.StartsWith("ack ", StringComparison.Ordinal))
        {
            Listener?.OnAcknowledged(int.Parse(line[4..], Num.Inv));
        }
    }

    protected override bool TryReadMotion(in string line, out MotionSample sample)
    {
        bool isPose = line.StartsWith("pose ", StringComparison.Ordinal);
        double x = isPose ? double.Parse(line[5..], Num.Inv) : 0;
        sample = new MotionSample(new Vector(x, 0, 0), Rotation.Identity, new Joints(0, 0, 0, 0, 0, 0), null);
        return isPose;
    }

    public int WireId(int actionId) => actionId;

    public void Adopt(int actionId)
    {
    }

    /// <summary>Feeds text as if the driver link had received it.</summary>
    internal void Receive(string text) => OnReceived(Encoding.ASCII.GetBytes(text));

    /// <summary>Splits text into lines; a line with '!' is not the protocol.</summary>
    private sealed class LineReader : IMessageReader<string>
    {
        private readonly StringBuilder _pending = new();

        public void Append(ReadOnlySpan<byte> data) => _pending.Append(Encoding.ASCII.GetString(data));

        public bool TryRead(out string message)
        {
            string text = _pending.ToString();
            int end = text.IndexOf('\n', StringComparison.Ordinal);
            message = end < 0 ? "" : text[..end];
            if (end < 0)
            {
                return false;
            }
            _pending.Remove(0, end + 1);
            return message.Contains('!', StringComparison.Ordinal)
                ? throw new RobotConnectionException($"Garbage from the test controller: {message}", message)
                : true;
        }
    }
}

/// <summary>Records what a driver reports, from any thread.</summary>
internal sealed class RecordingListener : IDeviceListener
{
    internal ConcurrentQueue<int> Acknowledged { get; } = new();

    internal ConcurrentQueue<MotionSample> Motion { get; } = new();

    internal ConcurrentQueue<MachinaException> Faults { get; } = new();

    public void OnAcknowledged(int id) => Acknowledged.Enqueue(id);

    public void OnMotion(in MotionSample sample) => Motion.Enqueue(sample);

    public void OnStopped(MachinaException reason) => throw new InvalidOperationException("The line protocol never stops.");

    public void OnResumed() => throw new InvalidOperationException("The line protocol never stops.");

    public void OnFailed(int id, string reason, string? code) => throw new InvalidOperationException("The line protocol never fails an action.");

    public void OnFailedAfter(int executedId, string reason, string? code) => throw new InvalidOperationException("The line protocol never fails an action.");

    public void OnFault(MachinaException error) => Faults.Enqueue(error);
}
