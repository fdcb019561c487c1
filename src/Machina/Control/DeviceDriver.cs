namespace Machina;

/// <summary>
/// The life of a link to a controller, shared by every brand's <see cref="IDeviceDriver"/>: the driver link and the side
/// links a brand opens (monitor, RTDE, script port), the handshake the controller sends when the driver link opens, the
/// receive loop that turns bytes into the brand's messages, failing exactly once (the handshake's waiter before it arrived,
/// <see cref="IDeviceListener.OnFault"/> after) and closing every link on disposal. A brand supplies its reader, what each
/// message means (<see cref="OnMessage"/>) and how it connects (<see cref="OpenAsync"/>), and implements the rest of
/// <see cref="IDeviceDriver"/> itself (<c>WireId</c>, <c>Adopt</c>, and <c>ResumeAsync</c> if its controller stops); <c>Send</c> is
/// shared: it puts the frame the brand encoded on the link.
/// </summary>
/// <typeparam name="TMessage">One message the controller sends on the driver link.</typeparam>
internal abstract partial class DeviceDriver<TMessage> : ILinkReceiver, IAsyncDisposable
{
    private readonly IMessageReader<TMessage> _reader;
    private readonly string _peer;
    private readonly TaskCompletionSource<DeviceHandshake> _handshake = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly List<TcpLink> _sideLinks = new(2);
    private int _failed;

    /// <summary>
    /// A driver that reads its link with <paramref name="reader"/>, logs to <paramref name="log"/>, measures its timeouts with
    /// <paramref name="time"/> and calls the other end <paramref name="peer"/> in messages ("controller").
    /// </summary>
    protected DeviceDriver(RobotLogger log, TimeProvider time, IMessageReader<TMessage> reader, string peer)
    {
        Log = log;
        Time = time;
        _reader = reader;
        _peer = peer;
    }

    /// <summary>The robot's log.</summary>
    protected RobotLogger Log { get; }

    /// <summary>The robot's clock, for every timeout.</summary>
    protected TimeProvider Time { get; }

    /// <summary>Who hears what the controller says; set when connecting.</summary>
    protected IDeviceListener? Listener { get; private set; }

    /// <summary>The driver link (actions out, acknowledgements in), or null before it opened.</summary>
    protected TcpLink? Link { get; private set; }

    /// <summary>True once the link failed or the driver was disposed: nothing more is read or reported.</summary>
    protected bool IsFailed => Volatile.Read(ref _failed) != 0;

    /// <summary>True once the handshake arrived or failed.</summary>
    protected bool IsHandshakeOver => _handshake.Task.IsCompleted;

    /// <summary>True once the handshake arrived.</summary>
    protected bool HasHandshake => _handshake.Task.IsCompletedSuccessfully;

    /// <inheritdoc cref="IDeviceDriver.RemoteAddress"/>
    public virtual string RemoteAddress => Link?.RemoteAddress ?? "";

    /// <inheritdoc cref="IDeviceDriver.ConnectAsync"/>
    public Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken)
    {
        Listener = listener;
        return OpenAsync(host, port, timeout, cancellationToken);
    }

    /// <inheritdoc cref="IDeviceDriver.Send"/>
    /// <remarks>A driver is codec and link: the brand encoded the frame when the action was issued; this only puts it on the link.</remarks>
    public bool Send(RobotAction action, ActionFrame frame)
    {
        TcpLink link = Link ?? throw new InvalidOperationException("the link is not open");
        if (frame.Note is string note)
        {
            Log.Warning(note);
        }
        // Kept before the bytes leave: a fast controller's acknowledgement, or its program's stop, may come back before Post returns.
        if (frame.Acknowledged)
        {
            Sent(action.Id);
        }
        if (frame.Bytes.Length > 0)
        {
            link.Post(frame.Bytes);
        }
        return frame.Acknowledged;
    }

    /// <summary>An action the controller will acknowledge was put on the link (a driver that names unacknowledged actions keeps it).</summary>
    protected virtual void Sent(int actionId)
    {
    }

    /// <summary>Opens the links of this brand and returns the handshake; throws <see cref="MachinaException"/> on failure.</summary>
    protected abstract Task<DeviceHandshake> OpenAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken);

    /// <summary>Handles one message of the driver link; throws a <see cref="MachinaException"/> to fail the link.</summary>
    protected abstract void OnMessage(in TMessage message);

    /// <summary>
    /// Connects the driver link to <paramref name="host"/>:<paramref name="port"/> and waits for the handshake, all within
    /// <paramref name="timeout"/>. A controller that accepts but stays silent is told as "did not send its
    /// <paramref name="greeting"/> … is <paramref name="driverName"/> running there?".
    /// </summary>
    protected async Task<DeviceHandshake> OpenDriverLinkAsync(string host, int port, TimeSpan timeout, string greeting, string driverName, CancellationToken cancellationToken)
    {
        long start = Time.GetTimestamp();
        StartLink(await TcpLink.ConnectAsync(host, port, timeout, Time, cancellationToken).ConfigureAwait(false));
        return await HandshakeAsync(Left(start, timeout),
            () => $"The controller at {host}:{port} accepted the connection but did not send its {greeting} within {Num.G(timeout.TotalSeconds)} s; is {driverName} running there?",
            cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Makes <paramref name="link"/> the driver link and starts reading it.</summary>
    protected void StartLink(TcpLink link)
    {
        Link = link;
        link.Start(this);
    }

    /// <summary>Connects a side link read by <paramref name="receiver"/>; it is closed with the driver, before the driver link.</summary>
    protected async Task<TcpLink> OpenSideLinkAsync(string host, int port, TimeSpan timeout, ILinkReceiver receiver, CancellationToken cancellationToken)
    {
        TcpLink link = await TcpLink.ConnectAsync(host, port, timeout, Time, cancellationToken).ConfigureAwait(false);
        lock (_sideLinks)
        {
            _sideLinks.Add(link);
        }
        link.Start(receiver, TcpLink.SideThreadName);
        return link;
    }

    /// <summary>Waits for the handshake within <paramref name="left"/>; when it does not come, fails with <paramref name="silence"/>.</summary>
    protected async Task<DeviceHandshake> HandshakeAsync(TimeSpan left, Func<string> silence, CancellationToken cancellationToken)
    {
        try
        {
            return await _handshake.Task.WaitAsync(left > TimeSpan.Zero ? left : TimeSpan.Zero, Time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            throw new RobotConnectionException(silence());
        }
    }

    /// <summary>Completes the handshake (the first call wins).</summary>
    protected void Handshake(DeviceHandshake handshake) => _handshake.TrySetResult(handshake);

    /// <summary>Fails a handshake still awaited without failing the link (a side link that broke while connecting).</summary>
    protected void FailHandshake(MachinaException error) => _handshake.TrySetException(error);

    /// <summary>What is left of <paramref name="timeout"/> since <paramref name="start"/> (a timestamp of <see cref="Time"/>), never negative.</summary>
    protected TimeSpan Left(long start, TimeSpan timeout)
    {
        TimeSpan left = timeout - Time.GetElapsedTime(start);
        return left > TimeSpan.Zero ? left : TimeSpan.Zero;
    }

    /// <inheritdoc/>
    public void OnReceived(ReadOnlySpan<byte> data)
    {
        if (IsFailed)
        {
            return;
        }
        _reader.Append(data);
        try
        {
            while (!IsFailed && _reader.TryRead(out TMessage message))
            {
                OnMessage(message);
            }
        }
        catch (MachinaException ex)
        {
            Fail(ex);
        }
    }

    /// <inheritdoc/>
    public void OnClosed(Exception? error) => Fail(error is null
        ? new RobotConnectionException($"The {_peer} closed the connection.")
        : new RobotConnectionException($"The connection to the {_peer} failed: {error.Message}", error));

    /// <summary>
    /// Fails the link once, whatever happens next or at the same time: the handshake's waiter gets the error while it waits,
    /// the listener afterwards. Nothing more is read or reported.
    /// </summary>
    private void Fail(MachinaException error)
    {
        if (Interlocked.Exchange(ref _failed, 1) != 0)
        {
            return;
        }
        if (!_handshake.Task.IsCompleted)
        {
            _handshake.TrySetException(error);
        }
        else
        {
            Listener?.OnFault(error);
        }
    }

    /// <summary>The links are about to close (<see cref="DisposeAsync"/>): what waits for an answer on them can stop waiting.</summary>
    protected virtual void Closing()
    {
    }

    /// <summary>
    /// Stops reporting, closes every link's socket (the side links in the order they opened, the driver link last), then waits
    /// for their loops: the controller sees the driver link close even while a side link's loop is still busy.
    /// </summary>
    public async ValueTask DisposeAsync()
    {
        Interlocked.Exchange(ref _failed, 1);
        Closing();
        TcpLink[] sideLinks;
        lock (_sideLinks)
        {
            sideLinks = [.. _sideLinks];
        }
        foreach (TcpLink link in sideLinks)
        {
            link.CloseSocket();
        }
        Link?.CloseSocket();
        foreach (TcpLink link in sideLinks)
        {
            await link.DisposeAsync().ConfigureAwait(false);
        }
        if (Link is not null)
        {
            await Link.DisposeAsync().ConfigureAwait(false);
        }
    }
}
