namespace Machina;

internal sealed partial class OnlineSession
{
    private volatile Connection? _link;
    private volatile ConnectionState _state = ConnectionState.Disconnected;
    private MachinaException? _stopReason;
    private MachinaException? _lastFault;
    private long _lastProgress;
    private ITimer? _watchdog;

    /// <summary>
    /// Where the link stands: the loop's one state, written only on the loop, read anywhere. Transitions: Disconnected → Connecting (<see cref="ConnectAsync"/>
    /// claimed <see cref="_connecting"/>); Connecting → Connected (handshake done, cursors set) or Disconnected (failed or refused);
    /// Connected → Stopped (<see cref="IDeviceListener.OnStopped"/>) → Connected (<see cref="IDeviceListener.OnResumed"/>); Connected or
    /// Stopped → Disconnected (<see cref="DisconnectAsync"/>, a fault, silence). Actions are released only while Connected.
    /// Connecting is not stored: it is Disconnected while a connection is claimed (the claim is read first, so a connection that
    /// just attached reads Connected, never Disconnected).
    /// </summary>
    internal ConnectionState State =>
        Volatile.Read(ref _connecting) is not null && _state == ConnectionState.Disconnected ? ConnectionState.Connecting : _state;

    /// <summary>True while a controller is linked (connected or stopped).</summary>
    internal bool IsConnected => State is ConnectionState.Connected or ConnectionState.Stopped;

    /// <summary>"host:port" of the connected controller, or empty.</summary>
    internal string RemoteAddress => _link?.Driver.RemoteAddress ?? "";

    /// <summary>
    /// Connects and starts releasing the buffered actions. A controller that reports its progress and knows the actions an
    /// earlier connection sent resumes exactly where it is (nothing is sent twice, targets are unchanged, see
    /// <see cref="Resume"/>); otherwise the controller's pose becomes the state of every cursor and the buffered actions'
    /// targets are recomputed from it (any that no longer apply are dropped with a warning).
    /// </summary>
    internal async Task ConnectAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        // One trip into the loop, to attach: the connection is claimed here (its reports are held from then on).
        Connection link = Claim();
        IDeviceDriver driver = link.Driver;
        DeviceHandshake handshake;
        try
        {
            handshake = await driver.ConnectAsync(host, port, link, timeout, cancellationToken).ConfigureAwait(false);
        }
        catch
        {
            // Its held reports go with it: a report of a link that is neither current nor claimed is ignored.
            Interlocked.CompareExchange(ref _connecting, null, link);
            await driver.DisposeAsync().ConfigureAwait(false);
            throw;
        }
        string? refusal = await AskAsync(() => Attach(link, handshake)).ConfigureAwait(false);
        if (refusal is not null)
        {
            await driver.DisposeAsync().ConfigureAwait(false);
            throw refusal == DisposedRefusal ? Disposed("connect") : new RobotConnectionException(refusal);
        }
    }

    /// <summary>
    /// Starts a connection on the caller's thread: a new driver and its link, claimed as <see cref="_connecting"/> when no other
    /// connection is claimed and the robot is disconnected (the claim comes first: a connection that attaches clears its claim
    /// only after it became Connected, so a second caller either finds the claim taken or reads Connected).
    /// </summary>
    private Connection Claim()
    {
        ConnectionState seen = State;
        if (_disposed)
        {
            throw Disposed("connect");
        }
        if (seen == ConnectionState.Disconnected)
        {
            var link = new Connection(this, _driverFactory());
            if (Interlocked.CompareExchange(ref _connecting, link, null) is null)
            {
                if (_state == ConnectionState.Disconnected)
                {
                    return link;
                }
                Volatile.Write(ref _connecting, null);
            }
            seen = State;
            _ = link.Driver.DisposeAsync().AsTask();   // never connected: nothing to wait for
        }
        throw new InvalidOperationException($"The robot is already {seen.ToString().ToLowerInvariant()}; call Disconnect first.");
    }

    /// <summary>What <see cref="Attach"/> returns when the robot was disposed during the handshake.</summary>
    private const string DisposedRefusal = "disposed";

    /// <summary>
    /// Makes a link whose handshake is done current (on the loop): sets the cursors and queues for it (<see cref="Resume"/>),
    /// then handles the reports it sent meanwhile, in order, and releases. Returns why the connection is refused, or null.
    /// </summary>
    private string? Attach(Connection link, DeviceHandshake handshake)
    {
        List<(Action Handle, bool IsMotion)> held = link.Held;
        if (_disposed)
        {
            Volatile.Write(ref _connecting, null);
            return DisposedRefusal;   // disposed during the handshake: the robot stays disconnected, nothing changes
        }
        string? refusal = null;
        WithIssueCursor(issue =>
        {
            LearnModel(handshake, issue);
            refusal = Resume(handshake, link.Driver, issue);
        });
        if (refusal is not null)
        {
            Volatile.Write(ref _connecting, null);
            return refusal;
        }
        _state = ConnectionState.Connected;
        _stopReason = null;
        _lastFault = null;
        _failure = null;
        _liveOnLink = false;
        _link = link;
        Volatile.Write(ref _connecting, null);   // after Connected: a second ConnectAsync finds the claim taken or reads Connected
        _lastProgress = _time.GetTimestamp();
        StartWatchdog(link);
        Log(LogLevel.INFO, $"Connected to {_host.Brand} robot \"{_host.Name}\" on {link.Driver.RemoteAddress} (driver {handshake.Version}).");
        foreach ((Action report, _) in held)
        {
            report();   // each handler checks that the link is still current (a held fault or failure ends it)
        }
        ReleaseReady();
        return null;
    }

    private void InitialiseCursors(DeviceHandshake handshake, RobotCursor issue)
    {
        _execution.ResetToReported(handshake.Position, handshake.Rotation, handshake.Axes, handshake.ExternalAxes);
        _release.CopyFrom(_execution);
        issue.CopyFrom(_execution);
        int count = _buffer.Count;
        for (int i = 0; i < count; i++)
        {
            RobotAction action = _buffer.Dequeue().Action;
            string? refusal = issue.TryApply(action);
            if (refusal is null)
            {
                _buffer.Enqueue(new Pending(action, null));   // re-targeted: encoded again when released
            }
            else
            {
                Log(LogLevel.WARNING, $"Dropped the waiting action {action.ToInstruction()} (id {action.Id}): {refusal}");
            }
        }
    }

    /// <summary>
    /// Closes the link. Actions sent but not confirmed stay pending (the robot may still run them); see <see cref="Resume"/>.
    /// Closing it before every issued action was executed (Disconnect right after issuing, as the original's examples did) says
    /// how many were left, as a warning. <paramref name="cancellationToken"/> ends the wait, not the closing: the link is
    /// detached on the loop and the driver disposed whether or not anyone still waits (a dispose that never ends, such as a
    /// link thread held by its receiver, no longer holds the caller).
    /// </summary>
    internal Task DisconnectAsync(CancellationToken cancellationToken = default)
    {
        Task closing = CloseLinkAsync();
        if (!cancellationToken.CanBeCanceled || closing.IsCompleted)
        {
            return closing;
        }
        // Abandoned on cancellation: its failure (a driver's dispose that throws) is still observed, as a background close's is.
        _ = closing.ContinueWith(static t => _ = t.Exception, CancellationToken.None,
            TaskContinuationOptions.OnlyOnFaulted | TaskContinuationOptions.ExecuteSynchronously, TaskScheduler.Default);
        return closing.WaitAsync(cancellationToken);
    }

    /// <summary>Detaches the current link on the loop, then disposes its driver (what <see cref="DisconnectAsync"/> waits for).</summary>
    private async Task CloseLinkAsync()
    {
        Connection? link = await AskAsync(() =>
        {
            Connection? current = _link;
            if (current is not null)
            {
                WarnUnexecuted(_inFlight.Count, _buffer.Count);
                Detach(new RobotConnectionException("The robot was disconnected before every action was executed."));
            }
            return current;
        }).ConfigureAwait(false);
        if (link is null)
        {
            return;
        }
        await link.Driver.DisposeAsync().ConfigureAwait(false);
        Log(LogLevel.INFO, $"Disconnected from {_host.Brand} robot \"{_host.Name}\".");
    }

    private void WarnUnexecuted(int sent, int unsent)
    {
        if (sent + unsent == 0)
        {
            return;
        }
        Log(LogLevel.WARNING, $"Disconnected from \"{_host.Name}\" with {Counted.Of(sent + unsent, "action")} not executed ({sent} sent and not " +
            $"confirmed, which the robot may still run; {unsent} never sent). Call WaitForCompletion before Disconnect to let the robot finish them.");
    }

    /// <summary>
    /// Forgets the current link (on the loop) and fails waiters. Actions sent but not confirmed stay in flight: whether
    /// the controller ran them is only known when it reports its progress at the next connection.
    /// </summary>
    private void Detach(MachinaException reason)
    {
        _link = null;
        _state = ConnectionState.Disconnected;
        _stopReason = null;
        _credit = 0;
        _watchdog?.Dispose();
        _watchdog = null;
        FailWaiters(reason);
    }

    /// <summary>The link failed: report it, keep every unconfirmed action, close the driver. Later calls for the same link do nothing.</summary>
    private void Fault(Connection link, MachinaException error)
    {
        if (!ReferenceEquals(_link, link))
        {
            return;
        }
        if (ReferenceEquals(_stoppedByUser, link))
        {
            // The program the user stopped ended and closed its link: that is the stop, not a lost connection.
            WithIssueCursor(issue => StopPending(link, issue));
            StopApplied(link);
            return;
        }
        Detach(error);
        _lastFault = error;
        Log(LogLevel.ERROR, $"Connection to \"{_host.Name}\" lost: {error.Message}");
        if (_host.IsListening(OnlineEvent.ConnectionLost))
        {
            _events.Post(new ConnectionLostArgs(error, PendingList(), _execution.Snapshot()));
        }
        _ = CloseQuietlyAsync(link.Driver);
    }

    private async Task CloseQuietlyAsync(IDeviceDriver driver)
    {
        try
        {
            await driver.DisposeAsync().ConfigureAwait(false);
        }
        catch (Exception ex)
        {
            Log(LogLevel.DEBUG, $"Closing the failed link threw {ex.GetType().Name}: {ex.Message}");
        }
    }

    private void OnAcknowledged(Connection link, int id, double? readValue)
    {
        if (ReferenceEquals(_link, link) && Acknowledge(id, readValue) is MachinaException fault)
        {
            Fault(link, fault);
        }
    }

    /// <summary>
    /// Executes the action acknowledged by its wire id <paramref name="id"/> and everything released before it (the controller
    /// acknowledges in order; a skipped acknowledgement is covered by a later one); a fault for an id nothing in flight has.
    /// <paramref name="readValue"/> is the value the controller read when the action is a read.
    /// </summary>
    private MachinaException? Acknowledge(int id, double? readValue)
    {
        int index = 0, found = -1;
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked && f.WireId == id)
            {
                found = index;
                break;
            }
            index++;
        }
        if (found < 0)
        {
            return new RobotConnectionException(
                $"The controller acknowledged action {id}, which is not waiting for execution (never sent, or already executed).", $"@{id}");
        }
        for (int i = 0; i < found; i++)
        {
            Execute(_inFlight.Dequeue());
        }
        InFlight acknowledged = _inFlight.Dequeue();
        Execute(acknowledged, _inFlight.Count, _inFlight.Count + _buffer.Count, readValue);
        _lastAcknowledgedId = acknowledged.Action.Id;
        _liveOnLink = false; // a live pose from before this acknowledgement is older than the target it confirms
        _lastProgress = _time.GetTimestamp();
        ReleaseReady();
        return null;
    }

    private void OnMotion(Connection link, in MotionSample sample)
    {
        if (!ReferenceEquals(_link, link))
        {
            return;
        }
        _liveOnLink = true;
        RobotCursor motion = _motion ??= new RobotCursor();
        motion.SetLivePose(sample.Position, sample.Rotation, sample.Axes, sample.ExternalAxes);
        if (_host.IsListening(OnlineEvent.Motion))
        {
            _events.Post(new MotionUpdateArgs(motion.Snapshot()));
        }
    }

    /// <summary>The controller stopped on its own: nothing more is released, waiters fail with the reason, the link stays.</summary>
    /// <remarks>A pause the user asked for (<paramref name="byUser"/>) is logged as information; a stop of the controller's own as an error.</remarks>
    private void OnStopped(Connection link, MachinaException reason, bool byUser = false)
    {
        if (!ReferenceEquals(_link, link) || _state != ConnectionState.Connected)
        {
            return;
        }
        _state = ConnectionState.Stopped;
        _stopReason = reason;
        _credit = 0;
        FailWaiters(reason);
        Log(byUser ? LogLevel.INFO : LogLevel.ERROR, $"\"{_host.Name}\" {(byUser ? "paused" : "stopped")}: {reason.Message} Nothing more is sent until it runs again (Resume, or at the pendant).");
        if (_host.IsListening(OnlineEvent.StopChanged))
        {
            _events.Post(new ControllerStoppedArgs(true, reason, PendingList(), _execution.Snapshot()));
        }
    }

    /// <summary>The controller runs again after a stop: releasing resumes where it was.</summary>
    private void OnResumed(Connection link)
    {
        if (!ReferenceEquals(_link, link) || _state != ConnectionState.Stopped)
        {
            return;
        }
        _state = ConnectionState.Connected;
        _stopReason = null;
        _lastProgress = _time.GetTimestamp();
        Log(LogLevel.INFO, $"\"{_host.Name}\" runs again; {Counted.Of(_inFlight.Count + _buffer.Count, "action")} {(_inFlight.Count + _buffer.Count == 1 ? "waits" : "wait")}.");
        if (_host.IsListening(OnlineEvent.StopChanged))
        {
            _events.Post(new ControllerStoppedArgs(false, null, PendingList(), _execution.Snapshot()));
        }
        ReleaseReady();
    }

    /// <summary>Asks a stopped controller to run again (through its driver) and waits until it does.</summary>
    internal async Task ResumeAsync(CancellationToken cancellationToken)
    {
        Connection link = await AskAsync(() =>
        {
            if (_disposed)
            {
                throw Disposed("resume");
            }
            if (_state != ConnectionState.Stopped || _link is null)
            {
                throw new InvalidOperationException(_state == ConnectionState.Connected
                    ? "The robot is running; there is nothing to resume."
                    : "The robot is not connected; call Connect (a reconnection resumes exactly where the controller is).");
            }
            return _link;
        }).ConfigureAwait(false);
        await link.Driver.ResumeAsync(cancellationToken).ConfigureAwait(false);
        await AskAsync(() =>
        {
            OnResumed(link);
            return true;
        }).ConfigureAwait(false);
    }

    private void StartWatchdog(Connection link)
    {
        TimeSpan timeout = ResponseTimeout;
        if (timeout == Timeout.InfiniteTimeSpan)
        {
            return;
        }
        TimeSpan period = TimeSpan.FromTicks(Math.Clamp(timeout.Ticks / 4, TimeSpan.TicksPerMillisecond * 10, TimeSpan.TicksPerSecond));
        // A tick is a message, posted only once the controller was silent longer than the timeout (CheckSilence adds the
        // expected duration of the action under way); _lastProgress is written by the loop only.
        _watchdog = _time.CreateTimer(_ =>
        {
            if (_time.GetElapsedTime(Volatile.Read(ref _lastProgress)) > timeout)
            {
                Post(() => CheckSilence(link, timeout));
            }
        }, null, period, period);
    }

    private void CheckSilence(Connection link, TimeSpan timeout)
    {
        if (!ReferenceEquals(_link, link))
        {
            return;
        }
        double expected = -1;
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked)
            {
                expected = f.ExpectedMs;
                break;
            }
        }
        if (expected < 0 || _state == ConnectionState.Stopped)
        {
            _lastProgress = _time.GetTimestamp();
            return;
        }
        TimeSpan silent = _time.GetElapsedTime(_lastProgress);
        // In milliseconds as doubles: an action expected to take longer than TimeSpan can hold (Wait(long.MaxValue), a
        // huge move at a tiny speed) must never overflow on this timer thread.
        if (silent.TotalMilliseconds > timeout.TotalMilliseconds + expected)
        {
            Fault(link, new RobotConnectionException(
                $"The controller stopped answering: no acknowledgement for {Num.F(silent.TotalSeconds, 1)} s while {Counted.Of(_inFlight.Count, "action")} {(_inFlight.Count == 1 ? "waits" : "wait")} for execution."));
        }
    }
}
