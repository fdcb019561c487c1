namespace Machina;

/// <summary>
/// The online half of a robot: the FIFO buffer of issued actions, the release policy, the Release, Execution and Motion
/// cursors, and the events. It holds no brand code: the brand's <see cref="IDeviceDriver"/> encodes and decodes, and its
/// <see cref="IOnlineBrand"/> refuses what the driver cannot run. Its state is owned by one loop (OnlineSession.Loop.cs):
/// issued actions, driver reports, watchdog ticks and the robot's calls are messages handled there in order, without a
/// lock; user code never runs in it (events and log lines go through an <see cref="EventPump"/>).
/// </summary>
internal sealed partial class OnlineSession : IActionStream
{
    private readonly IOnlineHost _host;
    private readonly ReleaseWindow _window;
    private readonly Func<IDeviceDriver> _driverFactory;
    private readonly IOnlineBrand? _brand;
    private readonly TimeProvider _time;
    private readonly EventPump _events;
    private readonly Queue<Pending> _buffer = new();
    private readonly Queue<InFlight> _inFlight = new();
    private readonly RobotCursor _release = new();
    private readonly RobotCursor _execution = new();
    private RobotCursor? _motion;
    private int _credit;

    /// <summary>The message an issued action posts (one delegate for all).</summary>
    private readonly Action _releaseReady;

    /// <summary>Creates the session of a robot whose issued state is <paramref name="issued"/> (called under the robot's issue lock).</summary>
    internal OnlineSession(IOnlineHost host, RobotCursor issued, ReleaseWindow window, Func<IDeviceDriver> driverFactory, IOnlineBrand? brand, TimeProvider time)
    {
        _brand = brand;
        _host = host;
        _window = window;
        _driverFactory = driverFactory;
        _time = time;
        _events = new EventPump(host.Raise);
        _releaseReady = ReleaseReady;
        DriverLog = new RobotLogger(host.Logger, (level, message) => _events.PostLog(host.Logger, level, message));
        _release.CopyFrom(issued);
        _execution.CopyFrom(issued);
    }

    /// <summary>
    /// The log the session's device drivers write to: their lines go to the robot's log on the event pump, in order with the
    /// events, so log sinks never run on a driver's loops nor on the session's loop.
    /// </summary>
    internal RobotLogger DriverLog { get; }

    /// <summary>How long the controller may stay silent beyond the expected duration of the action it works on.</summary>
    internal TimeSpan ResponseTimeout { get; set; } = TimeSpan.FromSeconds(30);

    /// <summary>
    /// A released action waiting for execution; <c>Acked</c> when the controller will acknowledge it, by <c>WireId</c> (the id the
    /// controller knows it by: the session alone maps a driver's reports back to actions). <c>Frame</c> is what was sent, kept
    /// for a resend with unchanged targets.
    /// </summary>
    private readonly record struct InFlight(RobotAction Action, bool Acked, double ExpectedMs, int WireId, ActionFrame? Frame);

    /// <summary>
    /// An action issued and not released yet, with its frame: encoded when it was issued, null once a reconnect re-targeted it
    /// (or when the robot has no codec): it is then encoded when it is released.
    /// </summary>
    private readonly record struct Pending(RobotAction Action, ActionFrame? Frame);

    /// <inheritdoc/>
    public void Enqueue(RobotAction action, ActionIssuedArgs? issued, ActionFrame? frame)
    {
        // Called under the robot's issue lock: the event and the action are queued in issue order; the loop releases it once
        // the robot calls ReleaseIssued after the lock. Running the loop here, under the lock, would let it apply a failure
        // (which takes the same lock, re-entrantly on this thread) between two actions of one Do: the second would miss it.
        if (issued is not null)
        {
            _events.Post(issued);
        }
        _inbox.Enqueue(new Pending(action, frame));
    }

    /// <inheritdoc/>
    public void ReleaseIssued() => Post(_releaseReady);

    /// <inheritdoc/>
    public string? WhyCannotStream(RobotAction action) => _brand?.WhyCannotStream(action);

    /// <inheritdoc/>
    public string? WhyCannotSend(RobotAction action, RobotCursor after) => Encode(action, after, out _);

    /// <inheritdoc/>
    public string? Encode(RobotAction action, RobotCursor after, out ActionFrame? frame)
    {
        string? refusal = null;
        frame = _brand?.Encode(action, after, out refusal);
        return refusal;
    }

    /// <summary>Actions issued and not executed yet, oldest first: first those sent to the controller, then those waiting.</summary>
    internal IReadOnlyList<RobotAction> GetPendingActions() => Ask(PendingList);

    private List<RobotAction> PendingList()
    {
        var list = new List<RobotAction>(_inFlight.Count + _buffer.Count);
        foreach (InFlight f in _inFlight)
        {
            list.Add(f.Action);
        }
        foreach (Pending p in _buffer)
        {
            list.Add(p.Action);
        }
        return list;
    }

    /// <summary>Numbers of actions waiting to be released and released but not executed.</summary>
    internal (int Buffered, int OnDevice) PendingCounts() => Ask(() => (_buffer.Count, _inFlight.Count));

    /// <summary>Drops every action not released yet; the issue cursor goes back to the state after the last released action.</summary>
    /// <returns>How many actions were dropped.</returns>
    internal int ClearPendingActions() => Ask(() =>
    {
        int count = 0;
        WithIssueCursor(issue =>
        {
            count = _buffer.Count;
            _buffer.Clear();
            issue.CopyFrom(_release);
            SignalWaiters();
        });
        return count;
    });

    /// <summary>Snapshots of the release, execution and motion cursors (motion is null before the first live pose).</summary>
    internal (RobotState Released, RobotState Executed, RobotState? Motion) Snapshots() =>
        Ask(() => (_release.Snapshot(), _execution.Snapshot(), _motion?.Snapshot()));

    /// <summary>Reads the execution cursor on the loop (online the robot's getters report the executed state, as the original did).</summary>
    internal T ReadExecution<T>(Func<RobotCursor, T> read) => Ask(() => read(_execution));

    /// <summary>How many motions the release and execution cursors solved themselves (tests and benchmarks count solves per action).</summary>
    internal int Solves() => Ask(() => _release.Solves + _execution.Solves);

    /// <summary>
    /// Completes once every issued action was executed and its events raised; fails when the link fails first, or with the
    /// <see cref="ActionFailedException"/> of an action the controller could not run (until the next connection).
    /// </summary>
    internal async Task WaitForCompletionAsync(CancellationToken cancellationToken)
    {
        if (_events.IsRaisingOnCurrentThread)
        {
            throw new InvalidOperationException(
                "WaitForCompletion cannot be called from an event handler: the completion is reported on the same thread. Await it elsewhere.");
        }
        Task task = await AskAsync(() => WhenPendingBelow(1, "wait for completion")).ConfigureAwait(false);
        await task.WaitAsync(cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Releases blocks while the window allows; executes released actions that nothing acknowledges once they are next.</summary>
    private void ReleaseReady()
    {
        if (_state != ConnectionState.Connected || _link is not { } link)
        {
            return;
        }
        while (true)
        {
            ExecuteUnacknowledgedHead();
            int block = _window.Take(_inFlight.Count, _buffer.Count, ref _credit);
            if (link.Driver.Capacity is int capacity && block > capacity - _inFlight.Count)
            {
                // The controller's buffer is the limit: the rest of the block stays open until acknowledgements free room.
                int room = Math.Max(0, capacity - _inFlight.Count);
                _credit += block - room;
                block = room;
            }
            if (block == 0)
            {
                break;
            }
            for (int i = 0; i < block; i++)
            {
                if (!ReleaseOne(link, _buffer.Dequeue()))
                {
                    return;
                }
            }
        }
        SignalWaiters();
    }

    /// <summary>Sends one action; false when the link failed doing so (then nothing more is released).</summary>
    private bool ReleaseOne(Connection link, Pending pending)
    {
        // Neither failure below can happen while the cursors agree and the brand refuses at issue time what its driver cannot
        // run; if one does, the action is never skipped silently: it goes back to the front of the buffer and the link is
        // closed, with nothing after it sent.
        RobotAction action = pending.Action;
        string? refusal = _release.TryApply(action);
        if (refusal is not null)
        {
            return FailRelease(link, pending, $"the state sent so far does not allow it: {refusal}", null);
        }
        ActionFrame frame;
        bool acknowledged;
        try
        {
            // The frame encoded at issue, from the same state as the release cursor's now; re-encoded only after a re-target.
            frame = pending.Frame ?? Reencode(action);
            acknowledged = link.Driver.Send(action, frame);
        }
        catch (Exception ex) when (ex is NotSupportedException or ArgumentException or InvalidOperationException)
        {
            return FailRelease(link, pending with { Frame = null }, $"it could not be encoded for the controller: {ex.Message}", ex);
        }
        if (_inFlight.Count == 0)
        {
            _lastProgress = _time.GetTimestamp();
        }
        _inFlight.Enqueue(new InFlight(action, acknowledged, ExpectedMilliseconds(action, _release), link.Driver.WireId(action.Id), frame));
        if (_host.IsListening(OnlineEvent.Released))
        {
            _events.Post(new ActionReleasedArgs(action, _buffer.Count, _release.Snapshot()));
        }
        return true;
    }

    /// <summary>Encodes an action whose frame a reconnect dropped, from the release cursor (the state after it).</summary>
    private ActionFrame Reencode(RobotAction action)
    {
        if (_brand is null)
        {
            return ActionFrame.Nothing;   // no codec (a test's driver): the driver decides
        }
        ActionFrame frame = _brand.Encode(action, _release, out string? refusal);
        return refusal is null ? frame : throw new ArgumentException(refusal);
    }

    private bool FailRelease(Connection link, Pending pending, string why, Exception? cause)
    {
        RobotAction action = pending.Action;
        PutBackInFront([pending]);
        Fault(link, new RobotConnectionException(
            $"{action.ToInstruction()} (id {action.Id}) was not sent: {why} Nothing after it was sent; remove it with ClearPendingActions.", cause));
        return false;
    }

    /// <summary>How long the controller should take for an action at the programmed speed, ms (0 for settings).</summary>
    private static double ExpectedMilliseconds(RobotAction action, RobotCursor after) => action switch
    {
        ActionWait w => w.Millis,
        // A wait for an input may last as long as its limit, or as long as it takes when it has none: not a silent controller.
        ActionWaitDigital d => d.TimeoutMillis > 0 ? d.TimeoutMillis : double.PositiveInfinity,
        _ when after.LastPathLength is double length && after.Speed > 0 => 1000 * length / after.Speed,
        _ => 0,
    };

    private void ExecuteUnacknowledgedHead()
    {
        while (_inFlight.TryPeek(out InFlight head) && !head.Acked)
        {
            Execute(_inFlight.Dequeue());
        }
    }

    private void Execute(InFlight entry) => Execute(entry, _inFlight.Count, _inFlight.Count + _buffer.Count);

    /// <summary>Applies an executed action to the execution cursor and reports it with the counts still pending after it.</summary>
    private void Execute(InFlight entry, int pendingOnDevice, int pendingTotal, double? readValue = null)
    {
        string? refusal = _execution.TryApply(entry.Action);
        if (refusal is not null)
        {
            Log(LogLevel.ERROR, $"The execution state could not follow {entry.Action.ToInstruction()}: {refusal}");
        }
        if (_host.IsListening(OnlineEvent.Executed))
        {
            _events.Post(new ActionExecutedArgs(entry.Action, pendingOnDevice, pendingTotal, _execution.Snapshot())
            {
                ReadValue = entry.Action is ActionReadInput ? readValue : null,
            });
        }
        if (entry.Action is ActionReadInput)
        {
            Delivered(entry.Action, readValue);
        }
    }

    /// <summary>
    /// Writes to the robot's log from the event loop, after the events queued so far: log sinks are user code, so they never
    /// run under the session's or the robot's locks, nor on a driver's loops.
    /// </summary>
    private void Log(LogLevel level, string message) => _events.PostLog(_host.Logger, level, message);

    /// <summary>Completes once every event queued so far was raised.</summary>
    internal async Task FlushEventsAsync()
    {
        // Through the loop first: every message posted so far is handled and its events are queued before the signal.
        var done = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        await AskAsync(() =>
        {
            _events.PostSignal(done, null);
            return true;
        }).ConfigureAwait(false);
        await done.Task.ConfigureAwait(false);
    }

    /// <summary>
    /// Stops raising events: after those already queued (<paramref name="raiseQueued"/>, when the robot goes back offline) or
    /// at once (when the robot is disposed). Completes when no handler runs any more (at once when called from a handler).
    /// </summary>
    internal Task CloseAsync(bool raiseQueued) => _events.StopAsync(raiseQueued);
}
