using System.Text;

namespace Machina;

/// <summary>
/// Host side of the KUKA link: a TCP client to Machina's KRL driver on EthernetKRL (batches of actions out, the state
/// <c>S</c> and acknowledgements <c>R</c> in) and, when the controller runs the monitor, a second client on port + 1 that
/// receives live poses (<c>P</c>). Never more than <see cref="KukaProtocol.Capacity"/> actions are on the controller
/// unacknowledged, so a batch can never overwrite a slot of the driver's ring that was not executed (fix of bug K7): the
/// session, which alone keeps what is in flight, reads <see cref="Capacity"/> and releases no more.
/// </summary>
internal sealed partial class KukaDriver : DeviceDriver<KukaElement>, IDeviceDriver
{
    private readonly double _motionUpdateRate;
    private TcpLink? _monitor;

    /// <summary>Creates a driver that logs to the robot's log, measures its timeouts with its clock and asks for its motion update rate.</summary>
    internal KukaDriver(DeviceContext context)
        : base(context.Logger, context.Time, new KukaXmlReader(), "controller")
    {
        _motionUpdateRate = context.MotionUpdateRate;
        _control = new ControlExchange(context.Time, TimeSpan.FromSeconds(10));
    }

    /// <summary>True when the monitor connection (live poses) is open.</summary>
    internal bool HasMonitor => _monitor is not null;

    /// <inheritdoc/>
    protected override async Task<DeviceHandshake> OpenAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        DeviceHandshake handshake = await OpenDriverLinkAsync(host, port, timeout, "state", "machina_kuka_driver", cancellationToken).ConfigureAwait(false);
        Requirement.Check(handshake.Version);
        _monitor = await OpenMonitorAsync(host, port + 1, new KukaXmlReader(),
            "Live poses are not available from this controller (no machina_kuka_monitor on the next port); there will be no motion updates.", cancellationToken).ConfigureAwait(false);
        _monitor?.Post(Encoding.ASCII.GetBytes(KukaMessages.MonitorRate(_motionUpdateRate)));
        return handshake;
    }

    /// <summary>The KRL driver this host needs: the one it ships (drivers/kuka), or a later 2.x.</summary>
    internal static DriverRequirement Requirement { get; } = new("KUKA", Version.Parse(KukaProtocol.DriverVersion),
        "Copy the files \"machina drivers kuka --host H --port P --out DIR\" writes (Robot.GetDeviceDriverModules) to the controller and start the driver again " +
        "(docs/getting-started.md); then connect again.");

    /// <summary>Encodes <paramref name="action"/> from <paramref name="after"/> with the KUKA codec and sends it (a driver used without a session).</summary>
    internal bool Send(RobotAction action, RobotCursor after) => Send(action, Codec.Encode(action, after, out _));

    private static KukaOnline Codec { get; } = new();

    /// <inheritdoc/>
    public int? Capacity => KukaProtocol.Capacity;

    /// <inheritdoc/>
    /// <remarks>KRL integers hold every action id, so the controller knows actions by their own ids.</remarks>
    public int WireId(int actionId) => actionId;

    /// <inheritdoc/>
    /// <remarks>Nothing to do: the session keeps what is in flight, counts the slots and maps the ids this driver reports.</remarks>
    public void Adopt(int actionId)
    {
    }

    /// <inheritdoc/>
    protected override void OnMessage(in KukaElement element)
    {
        switch (element.Name)
        {
            case KukaProtocol.Acknowledgement:
                Acknowledge(element.Integer("ID"), ReadValue(element));
                break;
            case KukaProtocol.Failure:
                Fail(element.Integer("ID"), element.Attribute("Text") ?? KukaFailure.Describe(0), element.Attribute("Code"));
                break;
            case KukaProtocol.Control:
                OnControl(element.Integer("K"));
                break;
            case KukaProtocol.State when !IsHandshakeOver:
                KukaState state = KukaState.Parse(element);
                Handshake(state.ToHandshake());
                break;
            case KukaProtocol.State:
                Log.Debug($"Ignored a second state report on one connection: {element}");
                break;
            default:
                throw new KukaProtocolException($"The controller sent <{element.Name}>, which is not part of the Machina KUKA driver protocol (S, R, F, C).", element.ToString());
        }
    }

    /// <summary>The driver could not run action <paramref name="id"/> and halted (it runs nothing more): the listener hears it.</summary>
    private void Fail(int id, string reason, string? code)
    {
        Log.Error($"The controller could not run action {id}: {reason}");
        Listener?.OnFailed(id, reason, code);
        if (code == Num.I(KukaFailure.Stopped))
        {
            // The stop's own report: the session closes the link on it, so the <C K="3"/> after it may never be read. The
            // failure is reported to the session first, so the stop finds it applied.
            OnControl(3);
        }
    }

    /// <summary>The value a read's acknowledgement carries (<c>V=""</c>), or null when there is none.</summary>
    private static double? ReadValue(in KukaElement element) =>
        element.Attribute("V") is string text && double.TryParse(text, System.Globalization.NumberStyles.Float, System.Globalization.CultureInfo.InvariantCulture, out double value) && double.IsFinite(value)
            ? value
            : null;

    private void Acknowledge(int wireId, double? readValue)
    {
        // Every acknowledgement after a read carries V (EthernetKRL keeps the value set last); the session keeps it for reads only.
        if (readValue is double value)
        {
            Listener?.OnAcknowledged(wireId, value);
            return;
        }
        Listener?.OnAcknowledged(wireId);
    }

    /// <inheritdoc/>
    protected override bool TryReadMotion(in KukaElement element, out MotionSample sample)
    {
        bool isPose = element.Name == KukaProtocol.Pose;
        sample = isPose ? KukaMessages.ReadSample(element) : default;
        return isPose;
    }
}
