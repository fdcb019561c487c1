using System.Text;

namespace Machina;

/// <summary>
/// Host side of the KUKA link: a TCP client to Machina's KRL driver on EthernetKRL (batches of actions out, the state
/// <c>S</c> and acknowledgements <c>R</c> in) and, when the controller runs the monitor, a second client on port + 1 that
/// receives live poses (<c>P</c>). Never more than <see cref="KukaProtocol.Capacity"/> actions are on the controller
/// unacknowledged, so a batch can never overwrite a slot of the driver's ring that was not executed (fix of bug K7):
/// actions beyond that wait here and go out as acknowledgements free slots.
/// </summary>
internal sealed class KukaDriver : IDeviceDriver, ILinkReceiver
{
    private readonly RobotLogger _log;
    private readonly TimeProvider _time;
    private readonly double _motionUpdateRate;
    private readonly KukaXmlReader _reader = new();
    private readonly object _gate = new();
    private readonly Queue<int> _awaiting = new();
    private readonly Queue<KukaInstruction> _held = new();
    private readonly StringBuilder _batch = new(1024);
    private readonly TaskCompletionSource<DeviceHandshake> _handshake = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private TcpLink? _link;
    private TcpLink? _monitor;
    private IDeviceListener? _listener;
    private string _version = "";
    private int _failed;

    /// <summary>Creates a driver that logs to the robot's log, measures its timeouts with its clock and asks for its motion update rate.</summary>
    internal KukaDriver(DeviceContext context)
    {
        _log = context.Logger;
        _time = context.Time;
        _motionUpdateRate = context.MotionUpdateRate;
    }

    /// <inheritdoc/>
    public string RemoteAddress => _link?.RemoteAddress ?? "";

    /// <summary>True when the monitor connection (live poses) is open.</summary>
    internal bool HasMonitor => _monitor is not null;

    /// <summary>Actions sent and not acknowledged yet (at most <see cref="KukaProtocol.Capacity"/>).</summary>
    internal int OnController
    {
        get
        {
            lock (_gate)
            {
                return _awaiting.Count - _held.Count;
            }
        }
    }

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
                $"The controller at {host}:{port} accepted the connection but did not send its state within {Num.G(timeout.TotalSeconds)} s; is machina_kuka_driver running there?");
        }
        if (handshake.Progress is null)
        {
            _log.Warning($"The KRL driver on the controller is version {_version}; this Machina ships {KukaProtocol.DriverVersion}, which reports its progress so that a reconnection resumes exactly. Load the driver from GetDeviceDriverModules.");
        }
        await ConnectMonitorAsync(host, port + 1, cancellationToken).ConfigureAwait(false);
        return handshake;
    }

    private async Task ConnectMonitorAsync(string host, int port, CancellationToken cancellationToken)
    {
        try
        {
            _monitor = await TcpLink.ConnectAsync(host, port, TimeSpan.FromSeconds(2), _time, cancellationToken).ConfigureAwait(false);
            _monitor.Start(new MonitorReceiver(this));
            _monitor.Post(Encoding.ASCII.GetBytes(KukaMessages.MonitorRate(_motionUpdateRate)));
        }
        catch (MachinaException)
        {
            _log.Info("Live poses are not available from this controller (no machina_kuka_monitor on the next port); there will be no motion updates.");
        }
    }

    /// <inheritdoc/>
    public bool Send(RobotAction action, RobotCursor releaseState)
    {
        if (_link is null)
        {
            throw new InvalidOperationException("the link is not open");
        }
        if (KukaActionEncoder.Encode(action, action.Id, releaseState) is not KukaInstruction instruction)
        {
            return false;
        }
        if (action is ActionMessage message && KukaActionEncoder.IsTruncated(message.Message))
        {
            _log.Warning($"KUKA messages hold {KukaProtocol.MaxTextLength} characters: the message of action {action.Id} is shown cut to \"{instruction.Text}\".");
        }
        if (action is ActionAttachTool && releaseState.Tool is Tool tool)
        {
            _log.Warning($"The weight and centre of gravity of tool \"{tool.Name}\" are not sent to KUKA controllers; set its load data on the controller.");
        }
        lock (_gate)
        {
            _awaiting.Enqueue(action.Id);
            _held.Enqueue(instruction);
            Flush();
        }
        return true;
    }

    /// <summary>Sends held actions while the controller has free slots, all in one batch (under <c>_gate</c>).</summary>
    private void Flush()
    {
        int free = KukaProtocol.Capacity - (_awaiting.Count - _held.Count);
        if (free <= 0 || _held.Count == 0 || _link is not TcpLink link)
        {
            return;
        }
        _batch.Clear();
        KukaInstruction.AppendBatch(_batch, Take(Math.Min(free, _held.Count)));
        byte[] bytes = Encoding.ASCII.GetBytes(_batch.ToString());
        link.Post(bytes);
    }

    private IEnumerable<KukaInstruction> Take(int count)
    {
        for (int i = 0; i < count; i++)
        {
            yield return _held.Dequeue();
        }
    }

    /// <inheritdoc/>
    /// <remarks>KRL integers hold every action id, so the controller knows actions by their own ids.</remarks>
    public int WireId(int actionId) => actionId;

    /// <inheritdoc/>
    public void Adopt(int actionId)
    {
        lock (_gate)
        {
            _awaiting.Enqueue(actionId);
        }
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
            while (Volatile.Read(ref _failed) == 0 && _reader.TryRead(out KukaElement element))
            {
                OnElement(element);
            }
        }
        catch (KukaProtocolException ex)
        {
            Fail(ex);
        }
    }

    /// <inheritdoc/>
    public void OnClosed(Exception? error) => Fail(error is null
        ? new RobotConnectionException("The controller closed the connection.")
        : new RobotConnectionException($"The connection to the controller failed: {error.Message}", error));

    private void OnElement(KukaElement element)
    {
        switch (element.Name)
        {
            case KukaProtocol.Acknowledgement:
                Acknowledge(element.Integer("ID"));
                break;
            case KukaProtocol.State when !_handshake.Task.IsCompleted:
                KukaState state = KukaState.Parse(element);
                _version = state.Version;
                _handshake.TrySetResult(state.ToHandshake());
                break;
            case KukaProtocol.State:
                _log.Debug($"Ignored a second state report on one connection: {element}");
                break;
            default:
                throw new KukaProtocolException($"The controller sent <{element.Name}>, which is not part of the Machina KUKA driver protocol (S, R).", element.ToString());
        }
    }

    private void Acknowledge(int wireId)
    {
        int actionId = wireId;
        lock (_gate)
        {
            int sent = _awaiting.Count - _held.Count, index = 0, found = -1;
            foreach (int awaiting in _awaiting)
            {
                if (index == sent)
                {
                    break;
                }
                if (awaiting == wireId)
                {
                    found = index;
                    break;
                }
                index++;
            }
            for (int i = 0; i <= found; i++)
            {
                actionId = _awaiting.Dequeue();
            }
        }
        // Outside the lock: the session takes its own lock and may call Send.
        _listener?.OnAcknowledged(actionId);
        lock (_gate)
        {
            Flush();
        }
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

    /// <summary>Reads the monitor connection: live poses (<c>P</c>). A failing monitor is logged; it never stops streaming.</summary>
    private sealed class MonitorReceiver(KukaDriver driver) : ILinkReceiver
    {
        private readonly KukaXmlReader _reader = new();
        private bool _stopped;

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (_stopped)
            {
                return;
            }
            _reader.Append(data);
            try
            {
                while (!_stopped && Volatile.Read(ref driver._failed) == 0 && _reader.TryRead(out KukaElement element))
                {
                    if (element.Name == KukaProtocol.Pose)
                    {
                        driver._listener?.OnMotion(KukaMessages.ReadSample(element));
                    }
                    else
                    {
                        Stop($"it sent {element}");
                    }
                }
            }
            catch (KukaProtocolException ex)
            {
                Stop(ex.Message);
            }
        }

        public void OnClosed(Exception? error) => Stop(error is null ? "the controller closed the monitor connection" : error.Message);

        private void Stop(string why)
        {
            if (!_stopped && Volatile.Read(ref driver._failed) == 0)
            {
                _stopped = true;
                driver._log.Warning($"Motion updates stopped: {why}.");
            }
        }
    }
}
