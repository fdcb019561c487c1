namespace Machina;

internal sealed partial class OnlineSession
{
    private Connection? _link;
    private bool _connecting;
    private long _lastProgress;
    private ITimer? _watchdog;

    /// <summary>True while a controller is connected.</summary>
    internal bool IsConnected => Volatile.Read(ref _link) is not null;

    /// <summary>"host:port" of the connected controller, or empty.</summary>
    internal string RemoteAddress => Volatile.Read(ref _link)?.Driver.RemoteAddress ?? "";

    /// <summary>
    /// Connects, takes the controller's pose as the state of every cursor, and starts releasing the buffered actions
    /// (their targets are recomputed from that pose; any that no longer apply are dropped with a warning).
    /// </summary>
    internal async Task ConnectAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        lock (_gate)
        {
            if (_link is not null || _connecting)
            {
                throw new InvalidOperationException("The robot is already connected (or connecting); call Disconnect first.");
            }
            _connecting = true;
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
                _connecting = false;
            }
            throw;
        }

        MachinaException? earlyFault;
        lock (_issue)
        {
            lock (_gate)
            {
                _connecting = false;
                InitialiseCursors(handshake);
                _link = link;
                link.IsReady = true;
                _lastProgress = _time.GetTimestamp();
                StartWatchdog(link);
                earlyFault = link.EarlyFault;
                if (earlyFault is null)
                {
                    ReleaseReady();
                }
            }
        }
        _robot.Logger.Info($"Connected to {_robot.Brand} robot \"{_robot.Name}\" on {driver.RemoteAddress} (driver {handshake.Version}).");
        if (earlyFault is not null)
        {
            Fault(link, earlyFault);
        }
    }

    private void InitialiseCursors(DeviceHandshake handshake)
    {
        _execution.Reset();
        if (handshake.Position is Vector position)
        {
            _execution.Position = _execution.PrevPosition = position;
        }
        if (handshake.Rotation is Rotation rotation)
        {
            _execution.Rotation = _execution.PrevRotation = rotation;
        }
        if (handshake.Axes is Joints axes)
        {
            _execution.Axes = _execution.PrevAxes = axes;
        }
        _execution.ExternalAxesCartesian = _execution.ExternalAxesJoints = handshake.ExternalAxes;
        _release.CopyFrom(_execution);
        _issue.CopyFrom(_execution);
        int count = _buffer.Count;
        for (int i = 0; i < count; i++)
        {
            RobotAction action = _buffer.Dequeue();
            string? refusal = _issue.TryApply(action);
            if (refusal is null)
            {
                _buffer.Enqueue(action);
            }
            else
            {
                _robot.Logger.Warning($"Dropped the waiting action {action.ToInstruction()} (id {action.Id}): {refusal}");
            }
        }
    }

    /// <summary>Closes the link. Actions sent but not confirmed go back to the front of the buffer (the robot may still run them).</summary>
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
        _robot.Logger.Info($"Disconnected from {_robot.Brand} robot \"{_robot.Name}\".");
    }

    /// <summary>Forgets the current link (under the lock): requeues unconfirmed actions, rewinds the release cursor, fails waiters.</summary>
    private void Detach(MachinaException reason)
    {
        _link = null;
        _credit = 0;
        _watchdog?.Dispose();
        _watchdog = null;
        if (_inFlight.Count > 0)
        {
            var keep = new List<RobotAction>(_inFlight.Count + _buffer.Count);
            foreach (InFlight f in _inFlight)
            {
                keep.Add(f.Action);
            }
            keep.AddRange(_buffer);
            _inFlight.Clear();
            _buffer.Clear();
            foreach (RobotAction a in keep)
            {
                _buffer.Enqueue(a);
            }
        }
        _release.CopyFrom(_execution);
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
            _robot.Logger.Error($"Connection to \"{_robot.Name}\" lost: {error.Message}");
            if (_robot.HasConnectionLostHandlers)
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
            _robot.Logger.Debug($"Closing the failed link threw {ex.GetType().Name}: {ex.Message}");
        }
    }

    private void OnAcknowledged(Connection link, int id)
    {
        MachinaException? fault = null;
        lock (_gate)
        {
            if (!ReferenceEquals(_link, link))
            {
                return;
            }
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
                fault = new RobotConnectionException(
                    $"The controller acknowledged action {id}, which is not waiting for execution (never sent, or already executed).", $"@{id}");
            }
            else
            {
                for (int i = 0; i <= found; i++)
                {
                    Execute(_inFlight.Dequeue());
                }
                _lastProgress = _time.GetTimestamp();
                ReleaseReady();
            }
        }
        if (fault is not null)
        {
            Fault(link, fault);
        }
    }

    private void OnMotion(Connection link, in MotionSample sample)
    {
        lock (_gate)
        {
            if (!ReferenceEquals(_link, link))
            {
                return;
            }
            RobotCursor motion = _motion ??= new RobotCursor();
            motion.Position = sample.Position;
            motion.Rotation = sample.Rotation;
            motion.Axes = sample.Axes;
            motion.ExternalAxesCartesian = sample.ExternalAxes;
            if (_robot.HasMotionHandlers)
            {
                _events.Post(new MotionUpdateArgs(motion.Snapshot()));
            }
        }
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
            if (expected < 0)
            {
                _lastProgress = _time.GetTimestamp();
                return;
            }
            TimeSpan silent = _time.GetElapsedTime(_lastProgress);
            if (silent > timeout + TimeSpan.FromMilliseconds(expected))
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

    /// <summary>One connection: routes a driver's reports to the session, ignoring them once the connection is replaced.</summary>
    private sealed class Connection(OnlineSession session, IDeviceDriver driver) : IDeviceListener
    {
        internal IDeviceDriver Driver { get; } = driver;

        /// <summary>Set once the handshake is done and the cursors are initialised.</summary>
        internal bool IsReady { get; set; }

        /// <summary>A fault reported before the connection became current.</summary>
        internal MachinaException? EarlyFault { get; private set; }

        public void OnAcknowledged(int id) => session.OnAcknowledged(this, id);

        public void OnMotion(in MotionSample sample) => session.OnMotion(this, sample);

        public void OnFault(MachinaException error)
        {
            lock (session._gate)
            {
                if (!IsReady)
                {
                    EarlyFault ??= error;
                    return;
                }
            }
            session.Fault(this, error);
        }
    }
}
