using System.Buffers.Binary;
using System.Text;

namespace Machina;

/// <summary>What one RTDE data package says about the robot, in Machina units.</summary>
/// <param name="Position">TCP position in mm (actual_TCP_pose).</param>
/// <param name="Rotation">TCP orientation (actual_TCP_pose's rotation vector).</param>
/// <param name="Joints">Joint angles in degrees (actual_q).</param>
/// <param name="RobotMode">robot_mode (7 = running).</param>
/// <param name="SafetyStatus">safety_status (1 = normal, 3 = protective stop, 6/7 = emergency stop…).</param>
/// <param name="RuntimeState">runtime_state (2 = playing, 4 = paused…).</param>
/// <param name="Executed">Our driver's last executed id (output_int_register_24).</param>
/// <param name="Received">Our driver's last received id (output_int_register_25).</param>
/// <param name="Instance">The instance number of the last of our driver programs that started (output_int_register_26).</param>
internal readonly record struct RtdeSample(Vector Position, Rotation Rotation, Joints Joints, int RobotMode, int SafetyStatus, uint RuntimeState, int Executed, int Received, int Instance = 0)
{
    /// <summary>runtime_state of a stopped program.</summary>
    public const uint Stopped = 1;

    /// <summary>runtime_state of a running program.</summary>
    public const uint Playing = 2;

    /// <summary>runtime_state of a paused program (held, dashboard <c>pause</c>).</summary>
    public const uint Paused = 4;

    /// <summary>True when a safety function stopped the robot (protective, safeguard or emergency stop, violation, fault).</summary>
    public bool IsSafetyStop => SafetyStatus is 3 or 5 or 6 or 7 or 8 or 9 or 12 or 13;

    /// <summary>A name for the safety status, for messages.</summary>
    public string SafetyName => SafetyStatus switch
    {
        1 => "normal",
        2 => "reduced",
        3 => "protective stop",
        5 or 12 => "safeguard stop",
        6 => "system emergency stop",
        7 => "robot emergency stop",
        8 => "safety violation",
        9 => "safety fault",
        13 => "three-position enabling stop",
        _ => "safety status " + SafetyStatus.ToString(Num.Inv),
    };
}

internal sealed partial class UrDriver
{
    /// <summary>The output recipe: state for the cursors and events, the safety and program state, and the driver's progress.</summary>
    internal static readonly string[] Recipe =
    [
        "timestamp", "actual_q", "actual_TCP_pose", "robot_mode", "safety_status", "runtime_state",
        "output_int_register_" + UrWire.ExecutedRegister.ToString(Num.Inv), "output_int_register_" + UrWire.ReceivedRegister.ToString(Num.Inv),
        "output_int_register_" + UrWire.InstanceRegister.ToString(Num.Inv),
    ];

    private static readonly string[] RecipeTypes = ["DOUBLE", "VECTOR6D", "VECTOR6D", "INT32", "INT32", "UINT32", "INT32", "INT32", "INT32"];

    private readonly object _rtdeGate = new();
    private readonly RtdePackageReader _rtdeReader = new();
    private TcpLink? _rtdeLink;
    private TaskCompletionSource<byte[]>? _reply;
    private byte _replyType;
    private TaskCompletionSource<RtdeSample> _nextSample = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private RtdeSample? _latest;
    private double _rtdeFrequency;
    private bool _reportedStop;

    /// <summary>The last state RTDE reported, or null before the first package.</summary>
    private RtdeSample? LatestSample
    {
        get
        {
            lock (_rtdeGate)
            {
                return _latest;
            }
        }
    }

    /// <summary>
    /// Waits for the first RTDE sample, the latest one included, for which <paramref name="until"/> holds, and returns it; null
    /// when <paramref name="timeout"/> passes first. A failed RTDE link throws <see cref="RobotConnectionException"/>.
    /// </summary>
    private async Task<RtdeSample?> WaitForSampleAsync(Func<RtdeSample, bool> until, TimeSpan timeout, CancellationToken cancellationToken)
    {
        long start = Time.GetTimestamp();
        while (true)
        {
            Task<RtdeSample> next;
            lock (_rtdeGate)
            {
                if (_latest is RtdeSample s && until(s))
                {
                    return s;
                }
                next = _nextSample.Task;
            }
            TimeSpan left = timeout - Time.GetElapsedTime(start);
            try
            {
                await next.WaitAsync(left > TimeSpan.Zero ? left : TimeSpan.Zero, Time, cancellationToken).ConfigureAwait(false);
            }
            catch (TimeoutException)
            {
                return null;
            }
        }
    }

    /// <summary>Connects to RTDE, negotiates protocol 2, subscribes to <see cref="Recipe"/> and returns the first package.</summary>
    /// <summary>
    /// Nothing answered at the address: says so with only what the user gave Connect (the RTDE port is derived from it) and what to
    /// pass instead.
    /// </summary>
    private RobotConnectionException Unreachable(string host, RobotConnectionException ex)
    {
        string cause = ex.InnerException is System.Net.Sockets.SocketException socket ? socket.Message : "nothing answered in time";
        return new RobotConnectionException(
            $"Could not connect to a UR controller at {host}, port {_ports.Script.ToString(Num.Inv)} ({cause}). Pass Connect the " +
            $"controller's address and its script port: Connect(\"192.168.1.10\", {UrPorts.StandardScript.ToString(Num.Inv)}) for a real UR " +
            "(or URSim) at that address, or the port \"machina sim ur\" printed for a virtual one.", ex);
    }

    private async Task<RtdeSample> ConnectRtdeAsync(string host, TimeSpan timeout, CancellationToken cancellationToken)
    {
        long start = Time.GetTimestamp();
        try
        {
            _rtdeLink = await OpenSideLinkAsync(host, _ports.Rtde, timeout, new RtdeReceiver(this), cancellationToken).ConfigureAwait(false);
        }
        catch (RobotConnectionException ex)
        {
            throw Unreachable(host, ex);
        }
        byte[] accepted = await RequestAsync(Rtde.RequestProtocolVersion, [0, (byte)Rtde.ProtocolVersion], start, timeout, cancellationToken).ConfigureAwait(false);
        if (accepted.Length != 1 || accepted[0] != 1)
        {
            throw new RobotConnectionException($"The UR controller at {host} does not speak RTDE protocol version 2 (software 3.4 / 5.0 or newer is needed).");
        }
        byte[] version = await RequestAsync(Rtde.GetControllerVersion, [], start, timeout, cancellationToken).ConfigureAwait(false);
        uint major = version.Length >= 4 ? BinaryPrimitives.ReadUInt32BigEndian(version) : 3;
        double maxRate = major >= 5 ? 500 : 125;
        _rtdeFrequency = Math.Min(_context.MotionUpdateRate, maxRate);

        byte[] names = Encoding.ASCII.GetBytes(string.Join(',', Recipe));
        var setup = new byte[8 + names.Length];
        BinaryPrimitives.WriteDoubleBigEndian(setup, _rtdeFrequency);
        names.CopyTo(setup, 8);
        byte[] reply = await RequestAsync(Rtde.SetupOutputs, setup, start, timeout, cancellationToken).ConfigureAwait(false);
        string[] types = reply.Length > 1 ? Encoding.ASCII.GetString(reply, 1, reply.Length - 1).Split(',') : [];
        if (!types.SequenceEqual(RecipeTypes))
        {
            var missing = Recipe.Where((_, i) => i >= types.Length || types[i] == Rtde.NotFound);
            throw new RobotConnectionException($"The UR controller at {host} cannot report {string.Join(", ", missing)} over RTDE (it answered \"{string.Join(',', types)}\"); Machina needs software 3.9 / 5.3 or newer.");
        }
        byte[] started = await RequestAsync(Rtde.Start, [], start, timeout, cancellationToken).ConfigureAwait(false);
        if (started.Length != 1 || started[0] != 1)
        {
            throw new RobotConnectionException($"The UR controller at {host} refused to start the RTDE data stream.");
        }
        Task<RtdeSample> first;
        lock (_rtdeGate)
        {
            first = _latest is RtdeSample s ? Task.FromResult(s) : _nextSample.Task;
        }
        try
        {
            return await first.WaitAsync(Left(start, timeout), Time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            throw new RobotConnectionException($"The UR controller at {host} started RTDE but sent no data within {Num.G(timeout.TotalSeconds)} s.");
        }
    }

    /// <summary>Sends one RTDE request and waits for the reply of the same type.</summary>
    private async Task<byte[]> RequestAsync(byte type, byte[] payload, long start, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var reply = new TaskCompletionSource<byte[]>(TaskCreationOptions.RunContinuationsAsynchronously);
        lock (_rtdeGate)
        {
            _reply = reply;
            _replyType = type;
        }
        _rtdeLink!.Post(Rtde.Package(type, payload));
        try
        {
            return await reply.Task.WaitAsync(Left(start, timeout), Time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            throw new RobotConnectionException($"The UR controller did not answer the RTDE request '{(char)type}' in time; is port {_ports.Rtde} its RTDE interface?");
        }
    }

    /// <summary>
    /// While the previous driver program still runs requests it received, waits (within <paramref name="left"/>) until it has
    /// run them, so that fewer are sent again. The progress itself is read only once the new program runs (<see cref="ProgressOfAsync"/>).
    /// </summary>
    private Task SettleAsync(TimeSpan left, CancellationToken cancellationToken) =>
        WaitForSampleAsync(s => s.Executed == s.Received || s.RuntimeState != RtdeSample.Playing || s.IsSafetyStop, left, cancellationToken);

    /// <summary>
    /// The progress to resume from, read once RTDE shows this connection's program (its instance number in register 26):
    /// a controller runs one program at a time, so every older one, and whatever it could still run, is stopped by then and
    /// the registers are final. The new program holds nothing yet, so what was received but not executed is sent again.
    /// </summary>
    private async Task<DeviceProgress> ProgressOfAsync(int instance, TimeSpan left, CancellationToken cancellationToken)
    {
        RtdeSample ours = await WaitForSampleAsync(s => s.Instance == instance, left, cancellationToken).ConfigureAwait(false)
            ?? throw new RobotConnectionException(
                $"The UR driver program connected back but RTDE never showed its instance number {instance.ToString(Num.Inv)} in output_int_register_{UrWire.InstanceRegister.ToString(Num.Inv)}: another program may have replaced it. Nothing was sent; connect again.");
        return new DeviceProgress(ours.Executed, ours.Executed);
    }

    private void OnRtdePackage(byte type, ReadOnlySpan<byte> payload)
    {
        if (type == Rtde.DataPackage)
        {
            OnSample(Decode(payload));
            return;
        }
        if (type == Rtde.TextMessage)
        {
            Log.Info("UR controller: " + TextOf(payload));
            return;
        }
        TaskCompletionSource<byte[]>? reply = null;
        lock (_rtdeGate)
        {
            if (_reply is not null && _replyType == type)
            {
                reply = _reply;
                _reply = null;
            }
        }
        reply?.TrySetResult(payload.ToArray());
    }

    private static string TextOf(ReadOnlySpan<byte> payload)
    {
        int length = payload.Length > 0 ? Math.Min(payload[0], payload.Length - 1) : 0;
        return Encoding.ASCII.GetString(payload.Slice(1, length));
    }

    /// <summary>Bytes of a data package of <see cref="Recipe"/>: recipe id, timestamp, two vectors, six 32-bit integers.</summary>
    internal const int PackageLength = 1 + 8 + 48 + 48 + 6 * 4;

    /// <summary>Reads a data package of <see cref="Recipe"/>: recipe id, timestamp, actual_q, actual_TCP_pose, modes and registers.</summary>
    internal static RtdeSample Decode(ReadOnlySpan<byte> payload)
    {
        if (payload.Length != PackageLength)
        {
            throw new RobotConnectionException($"The UR controller sent an RTDE data package of {payload.Length} bytes; the recipe has {PackageLength}.");
        }
        ReadOnlySpan<byte> p = payload[9..];
        Span<double> q = stackalloc double[6];
        Span<double> tcp = stackalloc double[6];
        for (int i = 0; i < 6; i++)
        {
            q[i] = Plausible(BinaryPrimitives.ReadDoubleBigEndian(p[(i * 8)..]) / UrScriptText.Rad, "actual_q");
            tcp[i] = Plausible(BinaryPrimitives.ReadDoubleBigEndian(p[(48 + i * 8)..]) / (i < 3 ? UrScriptText.Mm : UrScriptText.Rad), "actual_TCP_pose");
        }
        p = p[96..];
        return new RtdeSample(
            new Vector(tcp[0], tcp[1], tcp[2]),
            Rotation.FromRotationVector(new Vector(tcp[3], tcp[4], tcp[5])),
            new Joints(q[0], q[1], q[2], q[3], q[4], q[5]),
            BinaryPrimitives.ReadInt32BigEndian(p),
            BinaryPrimitives.ReadInt32BigEndian(p[4..]),
            BinaryPrimitives.ReadUInt32BigEndian(p[8..]),
            BinaryPrimitives.ReadInt32BigEndian(p[12..]),
            BinaryPrimitives.ReadInt32BigEndian(p[16..]),
            BinaryPrimitives.ReadInt32BigEndian(p[20..]));
    }

    /// <summary>Largest magnitude a pose or joint value of a real arm can have (mm or degrees); anything beyond is corrupt data.</summary>
    internal const double MaxPlausibleValue = 1e6;

    /// <summary><paramref name="value"/> (mm or degrees) when a real arm can report it; a connection error otherwise (not a number, infinite, absurd).</summary>
    private static double Plausible(double value, string field) =>
        double.IsFinite(value) && Math.Abs(value) <= MaxPlausibleValue
            ? value
            : throw new RobotConnectionException($"The UR controller sent {value.ToString(System.Globalization.CultureInfo.InvariantCulture)} in {field} of an RTDE data package: no arm reports that; the data is corrupt.");

    private void OnSample(RtdeSample sample)
    {
        TaskCompletionSource<RtdeSample> waiting;
        lock (_rtdeGate)
        {
            _latest = sample;
            waiting = _nextSample;
            _nextSample = new TaskCompletionSource<RtdeSample>(TaskCreationOptions.RunContinuationsAsynchronously);
        }
        waiting.TrySetResult(sample);
        if (!HasHandshake || IsFailed || IsProgramFailed)
        {
            return;
        }
        Listener?.OnMotion(new MotionSample(sample.Position, sample.Rotation, sample.Joints, null));
        if (IsStreamBroken(sample))
        {
            OnStreamBroken();
            return;
        }
        if (sample.RuntimeState == RtdeSample.Stopped && !sample.IsSafetyStop && sample.Instance == _instance)
        {
            OnProgramStopped(sample);
            return;
        }
        if (sample.IsSafetyStop && !_reportedStop)
        {
            _reportedStop = true;
            Listener?.OnStopped(new RobotStoppedException(
                $"The UR robot stopped: {sample.SafetyName}. Nothing more is sent; clear the cause, then call Resume (or unlock and play at the pendant).",
                sample.SafetyName));
        }
        else if (_reportedStop && !sample.IsSafetyStop && sample.RuntimeState == RtdeSample.Playing)
        {
            _reportedStop = false;
            Listener?.OnResumed();
        }
    }

    /// <summary>Reads the RTDE connection. A broken RTDE link is logged; the driver link decides whether the connection lives.</summary>
    private sealed class RtdeReceiver(UrDriver driver) : ILinkReceiver
    {
        private bool _stopped;

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (_stopped)
            {
                return;
            }
            driver._rtdeReader.Append(data);
            try
            {
                while (!_stopped && driver._rtdeReader.TryRead(out byte type, out ReadOnlySpan<byte> payload))
                {
                    driver.OnRtdePackage(type, payload);
                }
            }
            catch (Exception ex) when (ex is RobotConnectionException or ArgumentException)
            {
                Stop(ex.Message);
            }
        }

        public void OnClosed(Exception? error) => Stop(error is null ? "the controller closed the RTDE connection" : error.Message);

        private void Stop(string why)
        {
            if (_stopped || driver.IsFailed)
            {
                return;
            }
            _stopped = true;
            if (!driver.IsHandshakeOver)
            {
                driver.FailHandshake(new RobotConnectionException("RTDE failed: " + why));
                lock (driver._rtdeGate)
                {
                    // Nobody may be waiting for these: their exceptions are observed here, never left to the finalizer.
                    if (driver._reply is { } reply && reply.TrySetException(new RobotConnectionException("RTDE failed: " + why)))
                    {
                        _ = reply.Task.Exception;
                    }
                    if (driver._nextSample.TrySetException(new RobotConnectionException("RTDE failed: " + why)))
                    {
                        _ = driver._nextSample.Task.Exception;
                    }
                }
            }
            else
            {
                driver.Log.Warning($"Live state from the UR controller stopped: {why}. Stops are no longer detected.");
            }
        }
    }
}
