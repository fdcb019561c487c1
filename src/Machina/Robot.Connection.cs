namespace Machina;

public sealed partial class Robot
{
    private readonly ReleaseWindow _window = new();
    /// <summary>The online session while the robot is online (null offline); set under the issue lock, where actions are issued into it.</summary>
    private OnlineSession? _session;
    private ControlType _controlType = ControlType.Offline;

    /// <summary>Makes the link to a controller; tests replace it with a fake.</summary>
    internal Func<IDeviceDriver>? DriverFactory { get; set; }

    /// <summary>Replaces the brand's online support (what it refuses to stream); tests only.</summary>
    internal IOnlineBrand? OnlineBrandOverride { get; set; }

    /// <summary>Clock used for the response timeout; tests may replace it.</summary>
    internal TimeProvider Time { get; set; } = TimeProvider.System;

    /// <summary>
    /// Raised after each action is sent to the controller. Online events (this one, <see cref="ActionExecuted"/>,
    /// <see cref="MotionUpdate"/>, <see cref="ConnectionLost"/>, <see cref="ControllerStopped"/>, <see cref="ControllerResumed"/>
    /// and, online, <see cref="ActionIssued"/>) are raised one at a time, in order, by this robot's event loop: on a thread-pool
    /// thread (not always the same one), never on the thread that issued the action. A handler may issue new actions. After
    /// going offline or disposing the robot, no handler runs any more.
    /// </summary>
    public event ActionReleasedHandler? ActionReleased;

    /// <summary>Raised after the controller reports an action as executed, with the state after it and the pending counts.</summary>
    public event ActionExecutedHandler? ActionExecuted;

    /// <summary>Raised when the controller reports where the robot is while it moves (ABB: its monitor task).</summary>
    public event MotionUpdateHandler? MotionUpdate;

    /// <summary>Raised when the link to the controller fails; the actions not confirmed as executed are kept and listed.</summary>
    public event EventHandler<ConnectionLostArgs>? ConnectionLost;


    /// <summary>
    /// Raised when the controller stops on its own (a protective or emergency stop, reported by UR controllers): nothing more is
    /// sent, waiting calls fail with <see cref="RobotStoppedException"/>, and nothing is lost. See <see cref="Resume"/>.
    /// </summary>
    public event EventHandler<ControllerStoppedArgs>? ControllerStopped;

    /// <summary>
    /// Raised when the controller reports that it could not run an action (an unreachable target, a joint beyond its limits)
    /// and stopped: the state is where the robot really is, and no action after the failed one is reported executed.
    /// </summary>
    public event EventHandler<ActionFailedArgs>? ActionFailed;

    /// <summary>Raised when a stopped controller runs again (after <see cref="Resume"/> or at its pendant); sending goes on.</summary>
    public event EventHandler<ControllerStoppedArgs>? ControllerResumed;

    bool IOnlineHost.IsListening(OnlineEvent kind) => kind switch
    {
        OnlineEvent.Released => ActionReleased is not null,
        OnlineEvent.Executed => ActionExecuted is not null,
        OnlineEvent.Motion => MotionUpdate is not null,
        OnlineEvent.ConnectionLost => ConnectionLost is not null,
        OnlineEvent.StopChanged => ControllerStopped is not null || ControllerResumed is not null,
        OnlineEvent.Failed => ActionFailed is not null,
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown online event."),
    };

    IReadOnlyList<(LogLevel Level, string Message)>? IOnlineHost.WithIssueCursor(Action<RobotCursor> change)
    {
        lock (_issueLock)
        {
            change(_issueCursor);
            // Written by the session on its event pump, never under the lock (a cursor change there refuses nothing).
            return TakeLockedLog()?.ConvertAll(line => (line.Level, line.Message));
        }
    }

    /// <summary>Delivers an online event to its subscribers (called by the event loop; never throws).</summary>
    void IOnlineHost.Raise(MachinaEventArgs args)
    {
        switch (args)
        {
            case ActionIssuedArgs a when ActionIssued is { } h: RaiseSafely(h, a); break;
            case ActionReleasedArgs a when ActionReleased is { } h: RaiseSafely(h, a); break;
            case ActionExecutedArgs a when ActionExecuted is { } h: RaiseSafely(h, a); break;
            case MotionUpdateArgs a when MotionUpdate is { } h: RaiseSafely(h, a); break;
            case ConnectionLostArgs a when ConnectionLost is { } h: RaiseSafely(h, a); break;
            case ActionFailedArgs a when ActionFailed is { } h: RaiseSafely(h, a); break;
            case ControllerStoppedArgs { IsStopped: true } a when ControllerStopped is { } h: RaiseSafely(h, a); break;
            case ControllerStoppedArgs { IsStopped: false } a when ControllerResumed is { } h: RaiseSafely(h, a); break;
        }
    }

    /// <summary>How this robot receives its actions: offline (compiled into a program, the default) or online (streamed).</summary>
    public ControlType GetControlMode() => _controlType;

    /// <summary>
    /// Chooses offline (actions are compiled) or online (actions are streamed to a controller after <see cref="Connect(string, int)"/>).
    /// Online control is available for ABB, UR and KUKA robots. Disconnect before changing the mode of a connected robot.
    /// </summary>
    /// <returns>True when the mode is set.</returns>
    public bool ControlMode(ControlType mode)
    {
        mode = EnumText.RequireDefined(mode, nameof(mode));
        if (mode == ControlType.Stream)
        {
            mode = ControlType.Online;
        }
        ThrowIfDisposed("change the control mode");
        if (mode == _controlType)
        {
            return true;
        }
        if (_session is { IsConnected: true })
        {
            throw new InvalidOperationException("The robot is connected; call Disconnect before changing its control mode.");
        }
        if (mode == ControlType.Online)
        {
            IOnlineBrand? brand = OnlineBrandOverride ?? (DriverFactory is null ? OnlineBrands.For(Brand) : OnlineBrands.TryFor(Brand));
            Func<IDeviceDriver> factory = DriverFactory ?? CreateDriverFactory(brand!);
            lock (_issueLock)
            {
                ThrowIfDisposed("go online");   // again under the lock: a robot disposed meanwhile never gets a session
                _session = new OnlineSession(this, _issueCursor, _window, factory, brand, Time);
            }
        }
        else
        {
            OnlineSession? old;
            lock (_issueLock)
            {
                old = _session;
                _session = null;
            }
            int dropped = old?.GetPendingActions().Count ?? 0;
            if (dropped > 0)
            {
                Logger.Warning($"Going offline dropped {Counted.Of(dropped, "action")} that {(dropped == 1 ? "was" : "were")} not executed by the controller.");
            }
            // Events that already happened are still raised, before this returns: no handler runs after going offline.
            old?.CloseAsync(raiseQueued: true).GetAwaiter().GetResult();
        }
        _controlType = mode;
        return true;
    }

    /// <summary>Chooses "offline" or "online" ("stream" is an old name of online), any letter case.</summary>
    public bool ControlMode(string mode) => ControlMode(EnumText.Parse<ControlType>(mode, "control mode"));

    /// <summary>
    /// Who starts the driver on the controller: <see cref="ConnectionType.User"/> (you load and start it) or, on an ABB,
    /// <see cref="ConnectionType.Machina"/>: each <see cref="ConnectAsync"/> first installs and starts the driver through the
    /// controller's Robot Web Services (see <see cref="InstallDriverAsync"/> and <see cref="WebServices"/>).
    /// </summary>
    /// <returns>True when set; false (with a warning in the log) for Machina on a UR or KUKA.</returns>
    public bool ConnectionManager(ConnectionType type)
    {
        if (EnumText.RequireDefined(type, nameof(type)) == ConnectionType.User)
        {
            _installsDriver = false;
            return true;
        }
        if (BrandRegistry.For(Brand).InstallDriver is not null)
        {
            _installsDriver = true;
            return true;
        }
        Logger.Warning(MachinaManagerRefused);
        return false;
    }

    /// <summary>The warning for ConnectionManager("machina") on a UR or KUKA: what to do instead, and where it is explained.</summary>
    internal const string MachinaManagerRefused =
        "ConnectionManager(\"machina\") is available on ABB controllers only, so nothing changed: Machina does not load or start the driver " +
        "on a KUKA controller (load and start it by hand; its files come from \"machina drivers\" or GetDeviceDriverModules, then Connect); " +
        "on a UR there is nothing to load, Connect sends the driver script itself. " +
        "See docs/migrating.md#the-driver-is-loaded-by-hand.";

    /// <summary>Same as <see cref="ConnectionManager(ConnectionType)"/> with "user" or "machina" (any letter case).</summary>
    public bool ConnectionManager(string type) => ConnectionManager(EnumText.Parse<ConnectionType>(type, "connection type"));

    /// <summary>How long <see cref="Connect(string, int)"/> waits for the controller and its handshake (default 5 s).</summary>
    public TimeSpan ConnectTimeout { get; set; } = TimeSpan.FromSeconds(5);

    /// <summary>
    /// How long the controller may stay silent, beyond the time the current action should take at its programmed speed,
    /// before the connection is declared lost (default 30 s; <see cref="Timeout.InfiniteTimeSpan"/> turns the check off).
    /// Takes effect at the next connection.
    /// </summary>
    public TimeSpan ResponseTimeout { get; set; } = TimeSpan.FromSeconds(30);

    /// <summary>
    /// What happens, when connecting again, to actions sent before a controller restart and not confirmed: the controller's
    /// progress was reset (or it is another controller), so whether each ran is unknown. False (the default): they are not
    /// sent again; each ends failed (<see cref="ActionFailed"/>, reason "the controller restarted; this action may or may not
    /// have run", code "restarted"), a warning lists their ids, and the next wait for completion throws once; the actions never
    /// sent run as usual. True: they are sent again, for a program whose actions may safely run twice (absolute moves, outputs).
    /// Takes effect at the next connection.
    /// </summary>
    public bool ResendAfterControllerRestart { get; set; }

    /// <summary>True while connected to a controller (also while it is stopped).</summary>
    public bool IsConnected => _session?.IsConnected ?? false;

    /// <summary>Where the link to the controller stands: disconnected, connecting, connected, or stopped by the controller.</summary>
    public ConnectionState ConnectionState => _session?.State ?? ConnectionState.Disconnected;

    /// <summary>
    /// Asks a controller that stopped on its own (see <see cref="ControllerStopped"/>) or that <see cref="Pause"/> held to run
    /// again, once its cause is cleared, and waits until it does. The actions it holds run once each; the rest are sent after them.
    /// </summary>
    /// <exception cref="InvalidOperationException">The robot is not stopped.</exception>
    /// <exception cref="MachinaException">The controller refused or could not be reached.</exception>
    public Task ResumeAsync(CancellationToken cancellationToken = default)
    {
        ThrowIfDisposed("resume");
        return RequireSession("resume").ResumeAsync(cancellationToken);
    }

    /// <summary>Same as <see cref="ResumeAsync"/>, waiting for it.</summary>
    /// <returns>True once the controller runs again.</returns>
    public bool Resume()
    {
        ResumeAsync().GetAwaiter().GetResult();
        return true;
    }

    /// <summary>Connects to the driver running on a controller at <paramref name="host"/>:<paramref name="port"/> and waits for its handshake.</summary>
    /// <returns>True once connected.</returns>
    /// <exception cref="MachinaException">The controller could not be reached or did not answer as expected.</exception>
    public bool Connect(string host, int port)
    {
        ConnectAsync(host, port).GetAwaiter().GetResult();
        return true;
    }

    /// <summary>Connects to a driver on this computer (such as RobotStudio's virtual controller) at 127.0.0.1:7000.</summary>
    /// <returns>True once connected.</returns>
    /// <exception cref="MachinaException">Nothing answered there (the message says what to pass instead), or it did not answer as expected.</exception>
    public bool Connect()
    {
        try
        {
            return Connect(DefaultHost, DefaultPort);
        }
        catch (RobotConnectionException ex)
        {
            throw new RobotConnectionException(
                $"Connect() with no arguments connects to {DefaultHost}, port {DefaultPort} (a virtual controller on this computer); " +
                $"for another controller call Connect(address, port). {ex.Message}", ex);
        }
    }

    /// <summary>Where <see cref="Connect()"/> connects: a virtual controller on this computer.</summary>
    private const string DefaultHost = "127.0.0.1";

    /// <summary>The port <see cref="Connect()"/> uses (RobotStudio's and <c>machina sim</c>'s default).</summary>
    private const int DefaultPort = 7000;

    /// <summary>
    /// Connects to the driver on a controller and waits for its handshake (at most <see cref="ConnectTimeout"/>). The robot's
    /// reported pose, joints and external axes become the state of every cursor; actions issued before are then streamed.
    /// After a lost connection, a driver that reports its progress (Machina's, from 1.6) lets the robot resume exactly: actions
    /// it ran count as executed, actions it holds are awaited, only the rest is sent, and nothing runs twice.
    /// </summary>
    /// <exception cref="MachinaException">The controller could not be reached or did not answer as expected.</exception>
    public Task ConnectAsync(string host, int port, CancellationToken cancellationToken = default)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(host);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(port);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(port, 65535);
        ThrowIfDisposed("connect");
        OnlineSession session = RequireSession("connect");
        session.ResponseTimeout = ResponseTimeout;
        session.ResendAfterControllerRestart = ResendAfterControllerRestart;
        return _installsDriver && BrandRegistry.For(Brand).InstallDriver is not null
            ? InstallThenConnectAsync(session, host, port, cancellationToken)
            : session.ConnectAsync(host, port, ConnectTimeout, cancellationToken);
    }

    /// <summary>ConnectionManager("machina"): installs and starts the driver through Robot Web Services, then connects as usual.</summary>
    private async Task InstallThenConnectAsync(OnlineSession session, string host, int port, CancellationToken cancellationToken)
    {
        await InstallDriverAsync(host, port, cancellationToken).ConfigureAwait(false);
        await session.ConnectAsync(host, port, ConnectTimeout, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Closes the connection. Actions sent but not confirmed as executed are kept as pending (the robot may still run them).</summary>
    /// <returns>True (kept for programs written for the original Machina).</returns>
    public bool Disconnect()
    {
        DisconnectAsync().GetAwaiter().GetResult();
        return true;
    }

    /// <summary>Closes the connection (see <see cref="Disconnect"/>), waiting until the driver's links are closed.</summary>
    public Task DisconnectAsync() => DisconnectAsync(CancellationToken.None);

    /// <summary>
    /// Closes the connection (see <see cref="Disconnect"/>), waiting until the driver's links are closed or
    /// <paramref name="cancellationToken"/> is cancelled. Cancelling ends the wait, not the disconnection: the robot stops
    /// sending and ends disconnected all the same (actions sent but not confirmed stay pending), and the links finish closing
    /// by themselves.
    /// </summary>
    /// <exception cref="OperationCanceledException">The wait was cancelled before the links were closed.</exception>
    public Task DisconnectAsync(CancellationToken cancellationToken) => _session?.DisconnectAsync(cancellationToken) ?? Task.CompletedTask;

    /// <summary>Waits until every issued action was executed by the controller and its events were raised.</summary>
    /// <exception cref="MachinaException">The connection was lost (or closed) before that.</exception>
    public Task WaitForCompletionAsync(CancellationToken cancellationToken = default)
    {
        ThrowIfDisposed("wait for completion");
        return RequireSession("wait for completion").WaitForCompletionAsync(cancellationToken);
    }

    /// <summary>
    /// Waits until fewer than <paramref name="maxPending"/> issued actions wait to be executed, so a long program can be issued as
    /// the robot goes instead of all at once. Offline it returns at once (nothing waits for a controller).
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="maxPending"/> is less than 1.</exception>
    /// <exception cref="ActionFailedException">The controller could not run an action and stopped (until the next connection).</exception>
    /// <exception cref="MachinaException">The controller stopped, or the connection was lost or never made while the wait would last.</exception>
    public Task WaitForRoomAsync(int maxPending, CancellationToken cancellationToken = default)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxPending, 1);
        ThrowIfDisposed("wait for room");
        return _session?.WaitForRoomAsync(maxPending, cancellationToken) ?? Task.CompletedTask;
    }

    /// <summary>Waits until every issued action was executed, at most <paramref name="timeout"/>.</summary>
    /// <returns>True when everything was executed, false on timeout.</returns>
    /// <exception cref="MachinaException">The connection was lost before that.</exception>
    public bool WaitForCompletion(TimeSpan timeout)
    {
        try
        {
            WaitForCompletionAsync().WaitAsync(timeout).GetAwaiter().GetResult();
            return true;
        }
        catch (TimeoutException)
        {
            return false;
        }
    }

    /// <summary>
    /// Sets the release window the way the original Machina did: stream until <paramref name="maxActionsOnController"/>
    /// actions wait on the controller, then refill when <paramref name="minActionOnController"/> or fewer are left
    /// (BlockSize = max − min, PendingCount = min + 1). Defaults: 2 and 10. Can be called at any time.
    /// </summary>
    public bool StreamConfiguration(int minActionOnController, int maxActionsOnController)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(minActionOnController);
        if (maxActionsOnController <= minActionOnController)
        {
            throw new ArgumentOutOfRangeException(nameof(maxActionsOnController), maxActionsOnController,
                $"The maximum number of actions on the controller must be greater than the minimum ({minActionOnController}).");
        }
        _window.BlockSize = maxActionsOnController - minActionOnController;
        _window.PendingCount = minActionOnController + 1;
        return true;
    }

    /// <summary>How many actions are sent to the controller at once (1 or more; default 8). Can be changed at any time.</summary>
    public int BlockSize
    {
        get => _window.BlockSize;
        set => _window.BlockSize = value;
    }

    /// <summary>
    /// A new block is sent when fewer than this many sent actions are still unexecuted on the controller (1 or more; default 3,
    /// so at most 10 actions wait on the controller). Can be changed at any time.
    /// </summary>
    public int PendingCount
    {
        get => _window.PendingCount;
        set => _window.PendingCount = value;
    }

    /// <summary>Issued actions not executed yet, oldest first (sent but unconfirmed ones first). Empty offline.</summary>
    public IReadOnlyList<RobotAction> GetPendingActions() => _session?.GetPendingActions() ?? [];

    /// <summary>Cancels every issued action not sent to the controller yet; the robot's state goes back to the last sent action.</summary>
    /// <returns>How many actions were cancelled.</returns>
    public int ClearPendingActions() => _session?.ClearPendingActions() ?? 0;

    /// <summary>"host:port" of the connected controller, or an empty string.</summary>
    public string GetIP() => _session?.RemoteAddress ?? "";

    /// <summary>State after the last action sent to the controller (online), or after the last issued action (offline).</summary>
    public RobotState GetReleasedState() => _session?.Snapshots().Released ?? GetIssuedState();

    /// <summary>State after the last action the controller executed (online), or after the last issued action (offline).</summary>
    public RobotState GetExecutedState() => _session?.Snapshots().Executed ?? GetIssuedState();

    /// <summary>Where the controller last reported the robot to be while moving, or null when it has not reported yet.</summary>
    public RobotState? GetMotionState() => _session?.Snapshots().Motion;

    /// <summary>State after the last issued action.</summary>
    public RobotState GetIssuedState()
    {
        lock (_issueLock)
        {
            return _issueCursor.Snapshot();
        }
    }

    /// <summary>
    /// The driver files to load on the controller, by file name, with the connection placeholders filled in.
    /// Needs "HOSTNAME" (the controller address the driver listens on) and "PORT" (a number; the monitor uses PORT + 1);
    /// "MONITOR_RATE" (motion updates per second, default 50) is optional. Works in any control mode.
    /// </summary>
    public IReadOnlyDictionary<string, string> GetDeviceDriverModules(IReadOnlyDictionary<string, string> parameters)
    {
        ArgumentNullException.ThrowIfNull(parameters);
        return OnlineBrands.DriverModules(Brand, parameters);
    }

    /// <summary>Completes once every online event queued so far was raised (tests).</summary>
    internal Task FlushEventsAsync() => _session?.FlushEventsAsync() ?? Task.CompletedTask;

    private Func<IDeviceDriver> CreateDriverFactory(IOnlineBrand brand) =>
        () => brand.CreateDriver(new DeviceContext(_session?.DriverLog ?? Logger, Time, Name, Model, MotionUpdateRate));

    /// <summary>
    /// How many live pose reports per second the robot asks its controller for while connected (Hz, default 50), which set
    /// how often <see cref="MotionUpdate"/> is raised. UR: the RTDE frequency (at most 125, or 500 on e-Series); KUKA: the
    /// driver's report interval; ABB: set by MONITOR_RATE in the driver modules instead. Takes effect at the next connection.
    /// </summary>
    public double MotionUpdateRate
    {
        get => _motionUpdateRate;
        set => _motionUpdateRate = value > 0 && value <= 1000
            ? value
            : throw new ArgumentOutOfRangeException(nameof(MotionUpdateRate), value, "The motion update rate must be more than 0 and at most 1000 reports per second.");
    }

    private double _motionUpdateRate = 50;

    private OnlineSession RequireSession(string what) => _session
        ?? throw new InvalidOperationException($"Cannot {what} while the robot is offline; call ControlMode(\"online\") first.");
}
