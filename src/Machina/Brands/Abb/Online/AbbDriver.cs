namespace Machina;

/// <summary>
/// Host side of the ABB link: a TCP client to the RAPID driver (requests out, acknowledgements and the handshake in) and,
/// when the controller runs the monitor task, a second client on port + 1 that receives live poses (<c>$24</c>).
/// </summary>
internal sealed partial class AbbDriver : DeviceDriver<AbbMessage>, IDeviceDriver
{
    private TcpLink? _monitor;

    // Handshake parts ($20..$23, and $25 from driver 1.6), filled by the receive loop.
    private AbbDriverVersion? _version;
    private Vector? _position;
    private Rotation? _rotation;
    private Joints? _axes;
    private ExternalAxes? _externalAxes;
    private bool _hasExternalAxes;
    private DeviceProgress? _progress;

    /// <summary>The last <c>$27 id value;</c> (a read's value), handed over with the acknowledgement of that id.</summary>
    private (int WireId, double Value)? _read;

    /// <summary>Creates a driver that logs to the robot's log and measures its timeouts with <paramref name="time"/>.</summary>
    internal AbbDriver(RobotLogger log, TimeProvider time)
        : base(log, time, new AbbMessageReader(), "controller")
    {
        _control = new ControlExchange(time, TimeSpan.FromSeconds(10));
    }

    /// <summary>True when the monitor connection (live poses) is open.</summary>
    internal bool HasMonitor => _monitor is not null;

    /// <inheritdoc/>
    protected override async Task<DeviceHandshake> OpenAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        long start = Time.GetTimestamp();
        DeviceHandshake handshake = await OpenDriverLinkAsync(host, port, timeout, "handshake", "the Machina driver", cancellationToken).ConfigureAwait(false);
        Requirement.Check(handshake.Version);
        _monitor = await OpenMonitorAsync(host, port + 1, new AbbMessageReader(),
            "Real-time monitoring is not available on this controller (no monitor task on the next port); there will be no motion updates.", cancellationToken).ConfigureAwait(false);
        return await WithRobotTypeAsync(handshake, Left(start, timeout), cancellationToken).ConfigureAwait(false);
    }

    /// <summary>The RAPID driver this host needs: the one it ships (drivers/abb), or a later 1.x.</summary>
    internal static DriverRequirement Requirement { get; } = new("ABB", AbbMessageFormat.DriverVersion.ToVersion(),
        "Install this Machina's driver with \"machina drivers abb --install --host H\", or load the modules \"machina drivers abb --host H --port P --out DIR\" writes " +
        "(Robot.GetDeviceDriverModules) into the motion task and start it; then connect again.");

    /// <summary>Encodes <paramref name="action"/> from <paramref name="after"/> with the ABB codec and sends it (a driver used without a session).</summary>
    internal bool Send(RobotAction action, RobotCursor after) => Send(action, Codec.Encode(action, after, out _));

    private static AbbOnline Codec { get; } = new();

    /// <summary>The id sent on the wire: RAPID reads ids as 32-bit floats, so they wrap below 2^23 (fix of bug A10).</summary>
    internal static int WireId(int actionId) => ((actionId - 1) % AbbRequest.MaxId) + 1;

    /// <inheritdoc/>
    int IDeviceDriver.WireId(int actionId) => WireId(actionId);

    /// <inheritdoc/>
    /// <remarks>Nothing to do: the session keeps what is in flight and maps the wire ids this driver reports.</remarks>
    public void Adopt(int actionId)
    {
    }

    /// <inheritdoc/>
    protected override void OnMessage(in AbbMessage message)
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
                Log.Debug($"Ignored from the controller: {message}");
                break;
        }
    }

    private void Acknowledge(int wireId)
    {
        if (_read is (int readId, double value) && readId == wireId)
        {
            _read = null;
            Listener?.OnAcknowledged(wireId, value);
            return;
        }
        Listener?.OnAcknowledged(wireId);
    }
}
