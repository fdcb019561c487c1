namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>
    /// Calls waiting (on the loop) until fewer than <c>Below</c> issued actions wait to be executed: a wait for completion waits
    /// for fewer than 1, a wait for room for fewer than its window. Signalled through the event pump, after the events before them.
    /// </summary>
    private readonly List<(int Below, string What, TaskCompletionSource Signal)> _pendingWaiters = [];

    /// <summary>Actions issued (and drained from the inbox) that were not executed yet.</summary>
    private int PendingCount => _buffer.Count + _inFlight.Count;

    /// <summary>
    /// Completes once fewer than <paramref name="maxPending"/> issued actions wait to be executed and the events before were raised;
    /// fails as a wait for completion does (a failure, a stop, a lost or missing link while it would have to wait).
    /// </summary>
    internal async Task WaitForRoomAsync(int maxPending, CancellationToken cancellationToken)
    {
        Task task = await AskAsync(() => WhenPendingBelow(maxPending, "wait for room")).ConfigureAwait(false);
        await task.WaitAsync(cancellationToken).ConfigureAwait(false);
    }

    /// <summary>"1 action waits" or "N actions wait".</summary>
    private static string Waiting(int pending) => Counted.Of(pending, "action") + (pending == 1 ? " waits" : " wait");

    /// <summary>What a wait for fewer than <paramref name="below"/> pending actions waits for (on the loop).</summary>
    private Task WhenPendingBelow(int below, string what)
    {
        if (_disposed)
        {
            return Task.FromException(Disposed(what));
        }
        int pending = PendingCount;
        if (pending < below)
        {
            // After a failure the controller's program stopped: a caller streaming on must learn it, not issue into a closed link.
            if (_failure is not null)
            {
                return Task.FromException(_failure);
            }
            if (TakeNotResent() is { } notResent)
            {
                return Task.FromException(notResent);   // once: a restart left actions unsent whose outcome is unknown
            }
            var done = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            _events.PostSignal(done, null);
            return done.Task;
        }
        if (_state == ConnectionState.Stopped)
        {
            return Task.FromException(_stopReason!);
        }
        if (_link is null)
        {
            if (_failure is not null)
            {
                return Task.FromException(new RobotConnectionException(
                    $"{Waiting(pending)} to be executed, but the controller stopped after a failure ({_failure.Message}); connect again to run them.", _failure));
            }
            return Task.FromException(_lastFault is { } fault
                ? new RobotConnectionException($"The connection was lost ({fault.Message}) while {Waiting(pending)} to be executed; connect again to resume.", fault)
                : new RobotConnectionException($"{Waiting(pending)} to be executed but the robot is not connected; call Connect first."));
        }
        var signal = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        _pendingWaiters.Add((below, what, signal));
        return signal.Task;
    }

    /// <summary>Signals every waiter whose condition now holds (after executions, a clear, a release).</summary>
    private void SignalWaiters()
    {
        if (_pendingWaiters.Count == 0)
        {
            return; // the common case while streaming
        }
        int pending = PendingCount;
        Exception? notResent = null;
        foreach ((int below, _, TaskCompletionSource signal) in _pendingWaiters)
        {
            if (pending < below)
            {
                notResent ??= TakeNotResent();
                _events.PostSignal(signal, notResent);
            }
        }
        // Without a predicate: a lambda capturing 'pending' would allocate its closure on every call, waiters or not.
        for (int i = _pendingWaiters.Count - 1; i >= 0; i--)
        {
            if (pending < _pendingWaiters[i].Below)
            {
                _pendingWaiters.RemoveAt(i);
            }
        }
    }

    /// <summary>Fails every waiter with <paramref name="reason"/> (the link went away or the controller stopped).</summary>
    private void FailWaiters(Exception reason)
    {
        foreach ((_, _, TaskCompletionSource signal) in _pendingWaiters)
        {
            _events.PostSignal(signal, reason);
        }
        _pendingWaiters.Clear();
        FailReadWaiters(reason);
    }

    /// <summary>Takes every waiter away with what it waits for (disposal fails them directly: the event pump stops).</summary>
    private List<(string What, TaskCompletionSource Signal)> TakeWaiters()
    {
        List<(string What, TaskCompletionSource Signal)> taken = _pendingWaiters.ConvertAll(w => (w.What, w.Signal));
        _pendingWaiters.Clear();
        return taken;
    }
}
