namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>Most read values kept for a caller that has not asked for them yet (the oldest is forgotten first).</summary>
    private const int KeptReadValues = 256;

    /// <summary>Calls waiting for the value of a read, by action id (on the loop); signalled through the event pump, after the read's ActionExecuted.</summary>
    private readonly Dictionary<int, ReadWaiter> _readWaiters = [];

    /// <summary>Values of reads that ran before anyone asked for them, by action id; NaN when the value was lost (ran while disconnected).</summary>
    private readonly Dictionary<int, double> _readValues = [];
    private readonly Queue<int> _readOrder = new();

    private sealed class ReadWaiter
    {
        internal TaskCompletionSource Signal { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        internal double Value { get; set; }
    }

    /// <summary>
    /// The value the controller read for the read action <paramref name="actionId"/>, once it ran; fails when the read fails or is
    /// cancelled, the controller stops, or the link goes away first.
    /// </summary>
    internal async Task<double> ReadValueAsync(int actionId, CancellationToken cancellationToken)
    {
        (double? known, ReadWaiter? waiter) = await AskAsync(() => WhenRead(actionId)).ConfigureAwait(false);
        if (known is double value)
        {
            return value;
        }
        await waiter!.Signal.Task.WaitAsync(cancellationToken).ConfigureAwait(false);
        return waiter.Value;
    }

    /// <summary>The value already read, or a waiter for it (on the loop); throws when it can never come.</summary>
    private (double?, ReadWaiter?) WhenRead(int actionId)
    {
        if (_disposed)
        {
            throw Disposed("read an input");
        }
        if (_readValues.Remove(actionId, out double value))
        {
            return double.IsNaN(value) ? throw LostRead(actionId) : (value, null);
        }
        if (!_inFlight.Any(f => f.Action.Id == actionId) && !_buffer.Any(p => p.Action.Id == actionId))
        {
            throw _failure is not null
                ? new RobotConnectionException($"The read (id {actionId}) did not run: {_failure.Message}", _failure)
                : new InvalidOperationException($"Action {actionId} is not a read waiting for the controller, and no value was kept for it.");
        }
        if (_state == ConnectionState.Stopped)
        {
            throw _stopReason!;
        }
        if (_link is null)
        {
            throw new RobotConnectionException(_lastFault is { } fault
                ? $"The connection was lost ({fault.Message}) before the read (id {actionId}) ran; connect again to run it."
                : $"The read (id {actionId}) waits to be sent but the robot is not connected; call Connect first.");
        }
        var waiter = new ReadWaiter();
        _readWaiters[actionId] = waiter;
        return (null, waiter);
    }

    /// <summary>Hands the value of an executed read to its waiter, or keeps it (NaN: the controller ran it while disconnected).</summary>
    private void Delivered(RobotAction read, double? value)
    {
        if (_readWaiters.Remove(read.Id, out ReadWaiter? waiter))
        {
            waiter.Value = value ?? double.NaN;
            _events.PostSignal(waiter.Signal, value is null ? LostRead(read.Id) : null);
            return;
        }
        _readValues[read.Id] = value ?? double.NaN;
        _readOrder.Enqueue(read.Id);
        while (_readOrder.Count > KeptReadValues)
        {
            _readValues.Remove(_readOrder.Dequeue());
        }
    }

    private static RobotConnectionException LostRead(int actionId) =>
        new($"The read (id {actionId}) ran while the robot was disconnected, so its value is not known; read the input again.");

    /// <summary>Fails every read waiter with <paramref name="reason"/> (a failure, a stop, a lost link; on disposal directly).</summary>
    private void FailReadWaiters(Exception reason, bool direct = false)
    {
        foreach (ReadWaiter waiter in _readWaiters.Values)
        {
            if (direct)
            {
                waiter.Signal.TrySetException(reason);
            }
            else
            {
                _events.PostSignal(waiter.Signal, reason);
            }
        }
        _readWaiters.Clear();
    }
}
