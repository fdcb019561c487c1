using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;

namespace Machina.Simulation;

/// <summary>
/// A stand-in for a KUKA controller running Machina's KRL driver and monitor on EthernetKRL, listening on 127.0.0.1. It plays
/// the driver's part: sends its state (<c>S</c>) on every connection, reads batches of actions into its 100-slot ring, runs
/// them in order with the shared motion model and acknowledges each (<c>R</c>); the monitor (driver port + 1) reports poses
/// (<c>P</c>) at the interval the host asks for. Made for tests and demos (docs/protocol-kuka.md).
/// </summary>
public sealed partial class VirtualKukaController : VirtualController<VirtualKukaState>
{
    private readonly VirtualKukaControllerOptions _options;
    private TcpListener? _driverListener;
    private TcpListener? _monitorListener;
    private TimeSpan _monitorPeriod;
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
        _monitorPeriod = options.MonitorPeriod;
    }

    /// <summary>TCP port of the driver channel (batches, state and acknowledgements); 0 until started.</summary>
    public int Port { get; private set; }

    /// <summary>TCP port of the monitor channel (pose reports), always <see cref="Port"/> + 1; 0 until started.</summary>
    public int MonitorPort { get; private set; }

    /// <summary>How many pose reports (<c>P</c>) have been sent on the monitor port.</summary>
    public int MonitorReportsSent => Volatile.Read(ref _monitorReportsSent);

    /// <summary>Time between two pose reports now (set by the host's <c>MON</c>).</summary>
    public TimeSpan MonitorPeriod
    {
        get
        {
            if (Twin is { } twin)
            {
                return TimeSpan.FromMilliseconds(KrlValues.ToInt(twin.Modules[MonitorChannel].Data["mon_ms"].Value));
            }
            lock (Gate)
            {
                return _monitorPeriod;
            }
        }
    }

    /// <summary>Fault injection: send any text on the driver socket (for example garbage); false when no client is connected.</summary>
    public Task<bool> SendRawAsync(string text, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(text);
        return SendToClientAsync(Encoding.ASCII.GetBytes(text), cancellationToken);
    }

    /// <summary>Fault injection: send an acknowledgement for any id (for example one never sent); false when no client is connected.</summary>
    public Task<bool> SendAcknowledgementAsync(int id, CancellationToken cancellationToken = default) =>
        SendToClientAsync(Encoding.ASCII.GetBytes(KukaMessages.Acknowledgement(id)), cancellationToken);

    private protected override byte[] AcknowledgementBytes(int id) => Encoding.ASCII.GetBytes(KukaMessages.Acknowledgement(id));

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
        (_driverListener, _monitorListener) = LoopbackPorts.BindPair();
        Port = ((IPEndPoint)_driverListener.LocalEndpoint).Port;
        MonitorPort = Port + 1;
        if (_options.RunsKrl)
        {
            StartTwin(_driverListener, _monitorListener, token);
            return Task.CompletedTask;
        }
        // Like the KRL driver: whatever the last client sent is in the ring before the next one gets the state.
        Run(token => ServeDriverClientsAsync(_driverListener, GreetAsync, ReadBatchesAsync, token));
        Run(token => ServeClientsAsync(_monitorListener, ServeMonitorAsync, token));
        return Task.CompletedTask;
    }

    private protected override void StopListening()
    {
        _driverListener?.Stop();
        _monitorListener?.Stop();
    }

    /// <summary>The state on every connection: version, axes, pose and, from driver 2, the progress.</summary>
    private Task GreetAsync(NetworkStream stream, CancellationToken token)
    {
        VirtualKukaState s = State;
        string state = KukaMessages.State(s.Joints, s.Position, s.Rotation, LastExecutedId, LastReceivedId);
        if (_options.DriverVersion.Major < 2)
        {
            // The original's driver 1.0: no progress.
            state = state[..state.IndexOf(" Executed=", StringComparison.Ordinal)].Replace("VR=\"" + KukaProtocol.DriverVersion + "\"",
                $"VR=\"{_options.DriverVersion.Major}.{_options.DriverVersion.Minor}\"", StringComparison.Ordinal) + "></S>";
        }
        return stream.WriteAsync(Encoding.ASCII.GetBytes(state), token).AsTask();
    }

    private async Task ReadBatchesAsync(NetworkStream stream, CancellationToken token)
    {
        var bytes = new byte[4096];
        var reader = new KukaXmlReader();
        try
        {
            while (true)
            {
                int n = await stream.ReadAsync(bytes, token).ConfigureAwait(false);
                if (n == 0)
                {
                    return;
                }
                reader.Append(bytes.AsSpan(0, n));
                while (reader.TryRead(out KukaElement element))
                {
                    if (!await AcceptBatchAsync(element, token).ConfigureAwait(false))
                    {
                        return;
                    }
                }
            }
        }
        catch (KukaProtocolException e)
        {
            RecordError(e.Message + " Received: " + e.ReceivedText);
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException or System.Threading.Channels.ChannelClosedException)
        {
            // Client gone or controller stopping: like the driver, keep executing what is in the ring.
        }
    }

    /// <summary>Puts the actions of one batch into the ring; false (the real driver stops) for anything else or a full ring.</summary>
    private async Task<bool> AcceptBatchAsync(KukaElement batch, CancellationToken token)
    {
        if (batch.Name != KukaProtocol.Batch || batch.Children.Any(c => c.Name != KukaProtocol.Actions))
        {
            RecordError($"expected a batch <{KukaProtocol.Batch}><{KukaProtocol.Actions}>…, received {batch}");
            return false;
        }
        foreach (KukaElement action in batch.Children.SelectMany(list => list.Children))
        {
            if (action.Name != KukaProtocol.Action)
            {
                RecordError($"expected an action <{KukaProtocol.Action} …/>, received {action}");
                return false;
            }
            KukaInstruction instruction = KukaInstruction.Parse(action);
            if (RequestsHeld >= KukaProtocol.Capacity)
            {
                RecordError($"the host sent action {instruction.Id} while the {KukaProtocol.Capacity} slots of the ring hold actions not executed; the driver stops rather than overwrite one.");
                return false;
            }
            await EnqueueAsync(instruction, instruction.Id, action.ToString(), token).ConfigureAwait(false);
        }
        return true;
    }

    /// <summary>One monitor client: its report intervals are read while pose reports go out, until it leaves.</summary>
    private async Task ServeMonitorAsync(NetworkStream stream, CancellationToken token)
    {
        using var gone = CancellationTokenSource.CreateLinkedTokenSource(token);
        Task rates = ReadMonitorRatesAsync(stream, gone);
        await ReportAsync(stream, gone.Token).ConfigureAwait(false);
        await gone.CancelAsync().ConfigureAwait(false);
        await rates.ConfigureAwait(false);
    }

    /// <summary>Reads <c>MON</c> elements (the report interval) until the client leaves, then stops the reports.</summary>
    private async Task ReadMonitorRatesAsync(NetworkStream stream, CancellationTokenSource gone)
    {
        var bytes = new byte[256];
        var reader = new KukaXmlReader();
        try
        {
            while (true)
            {
                int n = await stream.ReadAsync(bytes, gone.Token).ConfigureAwait(false);
                if (n == 0)
                {
                    break;
                }
                reader.Append(bytes.AsSpan(0, n));
                while (reader.TryRead(out KukaElement element))
                {
                    if (element.Name == KukaProtocol.MonitorRate && element.Integer("Ms") > 0)
                    {
                        lock (Gate)
                        {
                            _monitorPeriod = TimeSpan.FromMilliseconds(Math.Min(element.Integer("Ms"), 3_600_000));
                        }
                    }
                }
            }
        }
        catch (KukaProtocolException e)
        {
            RecordError("monitor: " + e.Message);
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            // Client gone or stopping.
        }
        await gone.CancelAsync().ConfigureAwait(false);
    }

    /// <summary>Sends <c>P</c> reports until the client leaves or the controller stops.</summary>
    private async Task ReportAsync(NetworkStream stream, CancellationToken token)
    {
        try
        {
            while (true)
            {
                var s = State;
                await stream.WriteAsync(Encoding.ASCII.GetBytes(KukaMessages.Pose(s.Joints, s.Position, s.Rotation)), token).ConfigureAwait(false);
                Interlocked.Increment(ref _monitorReportsSent);
                await Task.Delay(MonitorPeriod, Clock, token).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            // Client gone or stopping: wait for the next client.
        }
    }
}
