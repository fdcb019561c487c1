namespace Machina;

internal sealed partial class OnlineSession
{
    private Connection? _link;
    private ConnectionState _state = ConnectionState.Disconnected;
    private MachinaException? _stopReason;
    private MachinaException? _lastFault;
    private long _lastProgress;
    private ITimer? _watchdog;

    /// <summary>
    /// Where the link stands. Transitions (all under <c>_gate</c>): Disconnected → Connecting (<see cref="ConnectAsync"/>);
    /// Connecting → Connected (handshake done, cursors set) or Disconnected (failed or refused); Connected → Stopped
    /// (<see cref="IDeviceListener.OnStopped"/>) → Connected (<see cref="IDeviceListener.OnResumed"/>); Connected or Stopped →
    /// Disconnected (<see cref="DisconnectAsync"/>, a fault, silence). Actions are released only while Connected.
    /// </summary>
    internal ConnectionState State
    {
        get
        {
            lock (_gate)
            {
                return _state;
            }
        }
    }

    /// <summary>True while a controller is linked (connected or stopped).</summary>
    internal bool IsConnected => State is ConnectionState.Connected or ConnectionState.Stopped;

    /// <summary>"host:port" of the connected controller, or empty.</summary>
    internal string RemoteAddress => Volatile.Read(ref _link)?.Driver.RemoteAddress ?? "";

    /// <summary>
    /// Connects and starts releasing the buffered actions. A controller that reports its progress and knows the actions an
    /// earlier connection sent resumes exactly where it is (nothing is sent twice, targets are unchanged, see
    /// <see cref="Resume"/>); otherwise the controller's pose becomes the state of every cursor and the buffered actions'
    /// targets are recomputed from it (any that no longer apply are dropped with a warning).
    /// </summary>
    internal async Task ConnectAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        lock (_gate)
        {
            if (_disposed)
            {
                throw Disposed("connect");
            }
            if (_state != ConnectionState.Disconnected)
            {
                throw new InvalidOperationException($"The robot is already {_state.ToString().ToLowerInvariant()}; call Disconnect first.");
            }
            _state = ConnectionState.Connecting;
        }
        IDeviceDriver driver;
        Connection link;
        DeviceHandshake handshake;
        try
        {
            driver = _driverFactory();
            link = new Connection(this, driver);
            try
            {
                handshake = await driver.ConnectAsync(host, port, link, timeout, cancellationToken).ConfigureAwait(false);
            }
            catch
            {
                await driver.DisposeAsync().ConfigureAwait(false);
                throw;
            }
        }
        catch
        {
            lock (_gate)
            {
                _state = ConnectionState.Disconnected;
            }
            throw;
        }

        MachinaException? earlyFault = null;
        string? refusal = null;
        bool failedEarly = false, disposed = false;
        _host.WithIssueCursor(issue =>
        {
            lock (_gate)
            {
                _state = ConnectionState.Disconnected;
                if (_disposed)
                {
                    disposed = true;   // disposed during the handshake: the robot stays disconnected, nothing changes
                    return;
                }
                refusal = Resume(handshake, driver, issue);
                earlyFault = link.EarlyFault;
                if (refusal is null)
                {
                    _state = ConnectionState.Connected;
                    _stopReason = null;
                    _lastFault = null;
                    _failure = null;
                    _liveOnLink = false;
                    _link = link;
                    link.IsReady = true;
                    _lastProgress = _time.GetTimestamp();
                    StartWatchdog(link);
                    earlyFault ??= AcknowledgeEarly(link);
                    if (earlyFault is null && link.EarlyFailure is { } failed)
                    {
                        earlyFault = Fail(link, failed.Id, failed.Reason, failed.Code, issue);
                        failedEarly = earlyFault is null;
                    }
                    else if (earlyFault is null)
                    {
                        if (link.EarlyMotion is MotionSample motion)
                        {
                            OnMotion(link, motion); // the monitor reported before the link became current (ABB, KUKA; UR's RTDE)
                        }
                        if (link.EarlyStop is MachinaException stop)
                        {
                            OnStopped(link, stop); // stopped while connecting (UR: RTDE showed it before the link became current)
                        }
                        ReleaseReady();
                    }
                }
            }
        });
        if (disposed)
        {
            await driver.DisposeAsync().ConfigureAwait(false);
            throw Disposed("connect");
        }
        if (refusal is not null)
        {
            await driver.DisposeAsync().ConfigureAwait(false);
            throw new RobotConnectionException(refusal);
        }
        Log(LogLevel.INFO, $"Connected to {_host.Brand} robot \"{_host.Name}\" on {driver.RemoteAddress} (driver {handshake.Version}).");
        if (earlyFault is not null)
        {
            Fault(link, earlyFault);
        }
        else if (failedEarly)
        {
            await CloseQuietlyAsync(driver).ConfigureAwait(false);
        }
    }

    private void InitialiseCursors(DeviceHandshake handshake, RobotCursor issue)
    {
        _execution.ResetToReported(handshake.Position, handshake.Rotation, handshake.Axes, handshake.ExternalAxes);
        _release.CopyFrom(_execution);
        issue.CopyFrom(_execution);
        int count = _buffer.Count;
        for (int i = 0; i < count; i++)
        {
            RobotAction action = _buffer.Dequeue();
            string? refusal = issue.TryApply(action);
            if (refusal is null)
            {
                _buffer.Enqueue(action);
            }
            else
            {
                Log(LogLevel.WARNING, $"Dropped the waiting action {action.ToInstruction()} (id {action.Id}): {refusal}");
            }
        }
    }

    /// <summary>Closes the link. Actions sent but not confirmed stay pending (the robot may still run them); see <see cref="Resume"/>.</summary>
    internal async Task DisconnectAsync()
    {
        Connection? link;
        lock (_gate)
        {
            link = _link;
            if (link is null)
            {
                return;
            }
            Detach(new RobotConnectionException("The robot was disconnected before every action was executed."));
        }
        await link.Driver.DisposeAsync().ConfigureAwait(false);
        Log(LogLevel.INFO, $"Disconnected from {_host.Brand} robot \"{_host.Name}\".");
    }

    /// <summary>
    /// Forgets the current link (under the lock) and fails waiters. Actions sent but not confirmed stay in flight: whether
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
        if (_completion is not null)
        {
            _events.PostSignal(_completion, reason);
            _completion = null;
        }
    }

    /// <summary>The link failed: report it, keep every unconfirmed action, close the driver. Later calls for the same link do nothing.</summary>
    private void Fault(Connection link, MachinaException error)
    {
        lock (_gate)
        {
            if (!ReferenceEquals(_link, link))
            {
                return;
            }
            Detach(error);
            _lastFault = error;
            Log(LogLevel.ERROR, $"Connection to \"{_host.Name}\" lost: {error.Message}");
            if (_host.IsListening(OnlineEvent.ConnectionLost))
            {
                _events.Post(new ConnectionLostArgs(error, PendingList(), _execution.Snapshot()));
            }
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
            _host.Logger.Debug($"Closing the failed link threw {ex.GetType().Name}: {ex.Message}");
        }
    }

    private void OnAcknowledged(Connection link, int id)
    {
        MachinaException? fault;
        lock (_gate)
        {
            if (!ReferenceEquals(_link, link))
            {
                return;
            }
            fault = Acknowledge(id);
        }
        if (fault is not null)
        {
            Fault(link, fault);
        }
    }

    /// <summary>Executes the acknowledged action and everything released before it (under the lock); a fault for an unknown id.</summary>
    private MachinaException? Acknowledge(int id)
    {
        int index = 0, found = -1;
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked && f.Action.Id == id)
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
        for (int i = 0; i <= found; i++)
        {
            Execute(_inFlight.Dequeue());
        }
        _lastAcknowledgedId = id;
        _liveOnLink = false; // a live pose from before this acknowledgement is older than the target it confirms
        _lastProgress = _time.GetTimestamp();
        ReleaseReady();
        return null;
    }

    private void OnMotion(Connection link, in MotionSample sample)
    {
        lock (_gate)
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
    }

    /// <summary>The controller stopped on its own: nothing more is released, waiters fail with the reason, the link stays.</summary>
    private void OnStopped(Connection link, MachinaException reason)
    {
        lock (_gate)
        {
            if (!ReferenceEquals(_link, link) || _state != ConnectionState.Connected)
            {
                return;
            }
            _state = ConnectionState.Stopped;
            _stopReason = reason;
            _credit = 0;
            if (_completion is not null)
            {
                _events.PostSignal(_completion, reason);
                _completion = null;
            }
            Log(LogLevel.ERROR, $"\"{_host.Name}\" stopped: {reason.Message} Nothing more is sent until it runs again (Resume, or at the pendant).");
            if (_host.IsListening(OnlineEvent.StopChanged))
            {
                _events.Post(new ControllerStoppedArgs(true, reason, PendingList(), _execution.Snapshot()));
            }
        }
    }

    /// <summary>The controller runs again after a stop: releasing resumes where it was.</summary>
    private void OnResumed(Connection link)
    {
        lock (_gate)
        {
            if (!ReferenceEquals(_link, link) || _state != ConnectionState.Stopped)
            {
                return;
            }
            _state = ConnectionState.Connected;
            _stopReason = null;
            _lastProgress = _time.GetTimestamp();
            Log(LogLevel.INFO, $"\"{_host.Name}\" runs again; {_inFlight.Count + _buffer.Count} actions wait.");
            if (_host.IsListening(OnlineEvent.StopChanged))
            {
                _events.Post(new ControllerStoppedArgs(false, null, PendingList(), _execution.Snapshot()));
            }
            ReleaseReady();
        }
    }

    /// <summary>Asks a stopped controller to run again (through its driver) and waits until it does.</summary>
    internal async Task ResumeAsync(CancellationToken cancellationToken)
    {
        Connection link;
        lock (_gate)
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
            link = _link;
        }
        await link.Driver.ResumeAsync(cancellationToken).ConfigureAwait(false);
        OnResumed(link);
    }

    private void StartWatchdog(Connection link)
    {
        TimeSpan timeout = ResponseTimeout;
        if (timeout == Timeout.InfiniteTimeSpan)
        {
            return;
        }
        TimeSpan period = TimeSpan.FromTicks(Math.Clamp(timeout.Ticks / 4, TimeSpan.TicksPerMillisecond * 10, TimeSpan.TicksPerSecond));
        _watchdog = _time.CreateTimer(_ => CheckSilence(link, timeout), null, period, period);
    }

    private void CheckSilence(Connection link, TimeSpan timeout)
    {
        MachinaException? fault = null;
        lock (_gate)
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
                fault = new RobotConnectionException(
                    $"The controller stopped answering: no acknowledgement for {Num.F(silent.TotalSeconds, 1)} s while {_inFlight.Count} actions wait for execution.");
            }
        }
        if (fault is not null)
        {
            Fault(link, fault);
        }
    }
}
