using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;

namespace Machina.Simulation;

/// <summary>
/// A stand-in for a KUKA controller listening on 127.0.0.1: it runs Machina's KRL driver and monitor (drivers/kuka, unchanged)
/// on a KRL interpreter with EthernetKRL, as a KR C4 would. The driver sends its state (<c>S</c>) on every connection, reads
/// batches of actions into its 100-slot ring, runs them in order on the twin's arm and acknowledges each (<c>R</c>); the
/// monitor (driver port + 1) reports poses (<c>P</c>) at the interval the host asks for. Made for tests and demos
/// (docs/protocol-kuka.md, docs/simulation.md).
/// </summary>
public sealed partial class VirtualKukaController : VirtualController<VirtualKukaState>
{
    private readonly VirtualKukaControllerOptions _options;
    private TcpListener? _driverListener;
    private TcpListener? _monitorListener;
    private int _monitorReportsSent;

    /// <summary>Creates a stopped controller; call <c>StartAsync</c> to listen.</summary>
    public VirtualKukaController(VirtualKukaControllerOptions? options = null)
        : this(options ?? new VirtualKukaControllerOptions(), 0)
    {
    }

    private VirtualKukaController(VirtualKukaControllerOptions options, int _)
        : base(options, VirtualKukaControllerOptions.DefaultStart, (position, rotation, joints) => new VirtualKukaState
        {
            Position = position,
            Rotation = rotation,
            Joints = joints,
            Speed = 20,
            Zone = 5,
        })
    {
        _options = options;
        _connections = new ConnectionLog(options.ConnectionSeen);
    }

    /// <summary>TCP port of the driver channel (batches, state and acknowledgements); 0 until started.</summary>
    public int Port { get; private set; }

    /// <summary>TCP port of the monitor channel (pose reports), always <see cref="Port"/> + 1; 0 until started.</summary>
    public int MonitorPort { get; private set; }

    /// <summary>How many pose reports (<c>P</c>) have been sent on the monitor port.</summary>
    public int MonitorReportsSent => Volatile.Read(ref _monitorReportsSent);

    /// <summary>Time between two pose reports now: the monitor's <c>mon_ms</c> (set by the host's <c>MON</c>), or the options' until started.</summary>
    public TimeSpan MonitorPeriod => Twin is { } twin
        ? TimeSpan.FromMilliseconds(KrlValues.ToInt(twin.Modules[MonitorChannel].Data["mon_ms"].Value))
        : _options.MonitorPeriod;

    /// <summary>Fault injection: send any text on the driver socket (for example garbage); false when no client is connected.</summary>
    public Task<bool> SendRawAsync(string text, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(text);
        return SendToClientAsync(Encoding.ASCII.GetBytes(text), cancellationToken);
    }

    /// <summary>Fault injection: send an acknowledgement for any id (for example one never sent); false when no client is connected.</summary>
    public Task<bool> SendAcknowledgementAsync(int id, CancellationToken cancellationToken = default) =>
        SendToClientAsync(AcknowledgementBytes(id), cancellationToken);

    /// <summary>The acknowledgement as the driver's EKI_Send of <c>R</c> writes it.</summary>
    private protected override byte[] AcknowledgementBytes(int id) =>
        Encoding.ASCII.GetBytes("<R ID=\"" + id.ToString(CultureInfo.InvariantCulture) + "\" />");

    /// <summary>An element that is not part of the protocol (neither <c>S</c> nor <c>R</c>).</summary>
    private protected override byte[] GarbageBytes(Random random)
    {
        var name = new StringBuilder("X");
        for (int i = random.Next(1, 8); i > 0; i--)
        {
            name.Append((char)('a' + random.Next(26)));
        }
        return Encoding.ASCII.GetBytes($"<{name}>{random.Next()}</{name}>");
    }

    private protected override Task ListenAsync(CancellationToken token)
    {
        (_driverListener, _monitorListener) = LoopbackPorts.BindPair(_options.ListenAddress, _options.ListenPort);
        Port = ((IPEndPoint)_driverListener.LocalEndpoint).Port;
        MonitorPort = Port + 1;
        StartTwin(_driverListener, _monitorListener, token);
        return Task.CompletedTask;
    }

    private protected override void StopListening()
    {
        _driverListener?.Stop();
        _monitorListener?.Stop();
    }
}
