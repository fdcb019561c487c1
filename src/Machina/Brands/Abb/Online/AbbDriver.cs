namespace Machina;

/// <summary>
/// Host side of the ABB link: a TCP client to the RAPID driver (requests out, acknowledgements and the handshake in) and,
/// when the controller runs the monitor task, a second client on port + 1 that receives live poses (<c>$24</c>).
/// </summary>
internal sealed partial class AbbDriver : IDeviceDriver, ILinkReceiver
{
    private readonly RobotLogger _log;
    private readonly TimeProvider _time;
    private readonly AbbMessageReader _reader = new();
    private readonly AwaitedAcknowledgements _awaiting = new(WireId);
    private readonly List<AbbRequest> _requests = new(4);
    private readonly TaskCompletionSource<DeviceHandshake> _handshake = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private byte[] _encoded = new byte[1024];
    private TcpLink? _link;
    private TcpLink? _monitor;
    private IDeviceListener? _listener;
    private int _failed;

    // Handshake parts ($20..$23, and $25 from driver 1.6), filled by the receive loop.
    private AbbDriverVersion? _version;
    private Vector? _position;
    private Rotation? _rotation;
    private Joints? _axes;
    private ExternalAxes? _externalAxes;
    private bool _hasExternalAxes;
    private DeviceProgress? _progress;

    /// <summary>Creates a driver that logs to the robot's log and measures its timeouts with <paramref name="time"/>.</summary>
    internal AbbDriver(RobotLogger log, TimeProvider time)
    {
        _log = log;
        _time = time;
    }

    /// <inheritdoc/>
    public string RemoteAddress => _link?.RemoteAddress ?? "";

    /// <summary>True when the monitor connection (live poses) is open.</summary>
    internal bool HasMonitor => _monitor is not null;

    /// <inheritdoc/>
    public async Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken)
    {
        long start = _time.GetTimestamp();
        _listener = listener;
        _link = await TcpLink.ConnectAsync(host, port, timeout, _time, cancellationToken).ConfigureAwait(false);
        _link.Start(this);
        TimeSpan left = timeout - _time.GetElapsedTime(start);
        DeviceHandshake handshake;
        try
        {
            handshake = await _handshake.Task.WaitAsync(left > TimeSpan.Zero ? left : TimeSpan.Zero, _time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            throw new RobotConnectionException(
                $"The controller at {host}:{port} accepted the connection but did not send its handshake within {Num.G(timeout.TotalSeconds)} s; is the Machina driver running there?");
        }
        CheckVersion(_version!.Value);
        await ConnectMonitorAsync(host, port + 1, cancellationToken).ConfigureAwait(false);
        return handshake;
    }

    private async Task ConnectMonitorAsync(string host, int port, CancellationToken cancellationToken)
    {
        try
        {
            _monitor = await TcpLink.ConnectAsync(host, port, TimeSpan.FromSeconds(2), _time, cancellationToken).ConfigureAwait(false);
            _monitor.Start(new MonitorReceiver(this));
        }
        catch (MachinaException)
        {
            _log.Info("Real-time monitoring is not available on this controller (no monitor task on the next port); there will be no motion updates.");
        }
    }

    private void CheckVersion(AbbDriverVersion version)
    {
        if (!version.IsSupported)
        {
            _log.Warning($"The driver on the controller is version {version}; this Machina needs {AbbDriverVersion.MinimumSupported.Major}.x from {AbbDriverVersion.MinimumSupported}. Load the driver from GetDeviceDriverModules.");
        }
    }

    /// <inheritdoc/>
    public bool Send(RobotAction action, RobotCursor releaseState)
    {
        TcpLink link = _link ?? throw new InvalidOperationException("the link is not open");
        int wireId = WireId(action.Id);
        _requests.Clear();
        int count = AbbActionEncoder.Encode(wireId == action.Id ? action : WithId(action, wireId), releaseState, _requests);
        if (count == 0)
        {
            return false;
        }
        int length = 0;
        bool acknowledged = false;
        foreach (AbbRequest request in _requests)
        {
            if (_encoded.Length - length < request.MaxEncodedLength)
            {
                Array.Resize(ref _encoded, Math.Max(_encoded.Length * 2, length + request.MaxEncodedLength));
            }
            length += request.EncodeTo(_encoded.AsSpan(length));
            acknowledged |= request.Id == wireId;
        }
        if (acknowledged)
        {
            Adopt(action.Id);
        }
        link.Post(_encoded.AsSpan(0, length));
        return acknowledged;
    }

    /// <summary>A copy of an action carrying the id to send (only for ids beyond what RAPID reads exactly).</summary>
    private static RobotAction WithId(RobotAction action, int wireId)
    {
        RobotAction copy = action.CloneUnissued();
        copy.Id = wireId;
        return copy;
    }

    /// <summary>The id sent on the wire: RAPID reads ids as 32-bit floats, so they wrap below 2^23 (fix of bug A10).</summary>
    internal static int WireId(int actionId) => ((actionId - 1) % AbbRequest.MaxId) + 1;

    /// <inheritdoc/>
    int IDeviceDriver.WireId(int actionId) => WireId(actionId);

    /// <inheritdoc/>
    /// <remarks>Also how <see cref="Send"/> records an action it sent: its acknowledgement is awaited in order.</remarks>
    public void Adopt(int actionId)
    {
        _awaiting.Expect(actionId);
    }

    /// <inheritdoc/>
    public void OnReceived(ReadOnlySpan<byte> data)
    {
        if (Volatile.Read(ref _failed) != 0)
        {
            return;
        }
        _reader.Append(data);
        try
        {
            while (Volatile.Read(ref _failed) == 0 && _reader.TryRead(out AbbMessage message))
            {
                OnMessage(message);
            }
        }
        catch (AbbProtocolException ex)
        {
            Fail(ex);
        }
    }

    /// <inheritdoc/>
    public void OnClosed(Exception? error) => Fail(error is null
        ? new RobotConnectionException("The controller closed the connection.")
        : new RobotConnectionException($"The connection to the controller failed: {error.Message}", error));

    private void OnMessage(in AbbMessage message)
    {
        switch (message.Kind)
        {
            case AbbMessageKind.Acknowledgement when message.Id > 0:
                Acknowledge(message.Id);
                break;
            case AbbMessageKind.Data:
                OnData(message);
                break;
            default:
                _log.Debug($"Ignored from the controller: {message}");
                break;
        }
    }

    private void Acknowledge(int wireId)
    {
        int actionId = _awaiting.Resolve(wireId);
        _listener?.OnAcknowledged(actionId);
    }

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
            _listener?.OnFault(error);
        }
    }

    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        Interlocked.Exchange(ref _failed, 1);
        if (_monitor is not null)
        {
            await _monitor.DisposeAsync().ConfigureAwait(false);
        }
        if (_link is not null)
        {
            await _link.DisposeAsync().ConfigureAwait(false);
        }
    }
}
