using System.Collections.Concurrent;
using System.Threading.Channels;

namespace Machina.Tests.Control;

/// <summary>A device driver without a network: records what is sent; the test (or an auto-acknowledging loop) answers.</summary>
internal sealed class FakeDriver : IDeviceDriver
{
    private readonly Channel<int>? _autoAcks;
    private readonly Task _autoLoop = Task.CompletedTask;

    /// <summary>Creates the fake; with <paramref name="autoAcknowledge"/> every acknowledged action is acknowledged from a background loop.</summary>
    internal FakeDriver(bool autoAcknowledge = false)
    {
        if (autoAcknowledge)
        {
            _autoAcks = Channel.CreateUnbounded<int>();
            _autoLoop = Task.Run(async () =>
            {
                await foreach (int id in _autoAcks.Reader.ReadAllAsync())
                {
                    Listener!.OnAcknowledged(id);
                }
            });
        }
    }

    internal DeviceHandshake Handshake { get; set; } =
        new("1.5.0", new Vector(300, 0, 500), Rotation.FlippedAroundY, new Joints(0, 0, 0, 0, 90, 0), null);

    internal IDeviceListener? Listener { get; private set; }

    /// <summary>Actions sent, in order.</summary>
    internal ConcurrentQueue<RobotAction> Sent { get; } = new();

    /// <summary>Sent and not acknowledged by the test yet (only actions that expect an acknowledgement).</summary>
    internal int Unacknowledged => _unacked;

    /// <summary>Largest number of sent actions waiting for acknowledgement at once.</summary>
    internal int MaxUnacknowledged { get; private set; }

    /// <summary>Actions that produce nothing to send (like MotionMode on ABB).</summary>
    internal Func<RobotAction, bool> Acknowledges { get; set; } = a => a is not (ActionMotionMode or ActionComment or ActionDefineTool);

    internal bool Disposed { get; private set; }

    /// <summary>The controller's buffer the session must respect (null: no limit of its own).</summary>
    public int? Capacity { get; set; }

    private int _unacked;

    public string RemoteAddress => "fake:1";

    /// <summary>What the controller reports while connecting, before the handshake is returned (before the link is current).</summary>
    internal Action<IDeviceListener>? DuringConnect { get; set; }

    public Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken)
    {
        Listener = listener;
        DuringConnect?.Invoke(listener);
        return Task.FromResult(Handshake);
    }

    /// <summary>Actions the fake cannot encode (Send throws NotSupportedException for them).</summary>
    internal Func<RobotAction, bool> CannotEncode { get; set; } = _ => false;

    /// <summary>What <see cref="ResumeAsync"/> does; by default it reports the controller running again.</summary>
    internal Func<IDeviceListener, Task>? Resume { get; set; }

    public Task ResumeAsync(CancellationToken cancellationToken)
    {
        if (Resume is null)
        {
            Listener!.OnResumed();
            return Task.CompletedTask;
        }
        return Resume(Listener!);
    }

    public bool Send(RobotAction action, ActionFrame frame)
    {
        if (CannotEncode(action))
        {
            throw new NotSupportedException("the fake cannot encode it");
        }
        Sent.Enqueue(action);
        bool acked = Acknowledges(action);
        if (acked)
        {
            int now = Interlocked.Increment(ref _unacked);
            MaxUnacknowledged = Math.Max(MaxUnacknowledged, now);
            _autoAcks?.Writer.TryWrite(action.Id);
        }
        OnSent?.Invoke(action);
        return acked;
    }

    /// <summary>Called on the sending thread (the session's loop) after each action is sent, like a controller answering at once.</summary>
    internal Action<RobotAction>? OnSent { get; set; }

    /// <summary>Ids of actions an earlier connection sent that this one was told the controller still holds.</summary>
    internal ConcurrentQueue<int> Adopted { get; } = new();

    public int WireId(int actionId) => actionId;

    public void Adopt(int actionId)
    {
        Adopted.Enqueue(actionId);
        Interlocked.Increment(ref _unacked);
    }

    /// <summary>Acknowledges an id as the controller would.</summary>
    internal void Ack(int id)
    {
        Interlocked.Decrement(ref _unacked);
        Listener!.OnAcknowledged(id);
    }

    public async ValueTask DisposeAsync()
    {
        Disposed = true;
        _autoAcks?.Writer.TryComplete();
        await _autoLoop;
    }
}
