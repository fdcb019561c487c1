using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>The RTDE outputs the virtual controller knows, with their types (UR's RTDE guide); others answer NOT_FOUND.</summary>
    private static readonly Dictionary<string, string> OutputTypes = new(StringComparer.Ordinal)
    {
        ["timestamp"] = "DOUBLE",
        ["actual_q"] = "VECTOR6D",
        ["target_q"] = "VECTOR6D",
        ["actual_qd"] = "VECTOR6D",
        ["actual_TCP_pose"] = "VECTOR6D",
        ["target_TCP_pose"] = "VECTOR6D",
        ["actual_TCP_speed"] = "VECTOR6D",
        ["robot_mode"] = "INT32",
        ["safety_mode"] = "INT32",
        ["safety_status"] = "INT32",
        ["runtime_state"] = "UINT32",
        ["speed_scaling"] = "DOUBLE",
        ["target_speed_fraction"] = "DOUBLE",
        ["actual_digital_output_bits"] = "UINT64",
    };

    private readonly List<RtdeSubscriber> _subscribers = [];
    private readonly Lock _rtdeGate = new();
    private CancellationTokenSource _rtdeWake = new();
    private int _rtdePackagesSent;

    /// <summary>How many RTDE data packages have been sent, to all clients.</summary>
    public int RtdePackagesSent => Volatile.Read(ref _rtdePackagesSent);

    /// <summary>The type of an RTDE output name, or <c>NOT_FOUND</c>.</summary>
    internal static string TypeOf(string name)
    {
        if (OutputTypes.TryGetValue(name, out string? type))
        {
            return type;
        }
        const string register = "output_int_register_";
        return name.StartsWith(register, StringComparison.Ordinal) && int.TryParse(name.AsSpan(register.Length), System.Globalization.NumberStyles.None, Num.Inv, out int n) && n is >= 0 and <= 47
            ? "INT32"
            : Rtde.NotFound;
    }

    private Task AcceptRtdeClientsAsync(CancellationToken token) => AcceptAsync(_rtdeListener!, ServeRtdeAsync, token);

    /// <summary>One RTDE client: version negotiation, controller version, output setup, start and pause; data goes out from <see cref="SendRtdeAsync"/>.</summary>
    private async Task ServeRtdeAsync(TcpClient client, CancellationToken token)
    {
        var stream = client.GetStream();
        var subscriber = new RtdeSubscriber(stream);
        var reader = new RtdePackageReader();
        var bytes = new byte[4096];
        ushort protocol = 1;
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
                while (reader.TryRead(out byte type, out ReadOnlySpan<byte> payload))
                {
                    byte[] reply = Answer(type, payload, subscriber, ref protocol);
                    if (reply.Length > 0)
                    {
                        await subscriber.WriteAsync(reply, token).ConfigureAwait(false);
                    }
                }
            }
        }
        catch (RobotConnectionException e)
        {
            RecordError("RTDE: " + e.Message);
        }
        finally
        {
            lock (_rtdeGate)
            {
                _subscribers.Remove(subscriber);
            }
        }
    }

    /// <summary>The reply package to one request (empty for none).</summary>
    private byte[] Answer(byte type, ReadOnlySpan<byte> payload, RtdeSubscriber subscriber, ref ushort protocol)
    {
        switch (type)
        {
            case Rtde.RequestProtocolVersion:
                ushort asked = payload.Length >= 2 ? BinaryPrimitives.ReadUInt16BigEndian(payload) : (ushort)0;
                bool accepted = asked is 1 or 2;
                if (accepted)
                {
                    protocol = asked;
                }
                return Rtde.Package(type, [accepted ? (byte)1 : (byte)0]);
            case Rtde.GetControllerVersion:
                var version = new byte[16];
                BinaryPrimitives.WriteUInt32BigEndian(version, (uint)_options.ControllerVersion.Major);
                BinaryPrimitives.WriteUInt32BigEndian(version.AsSpan(4), (uint)_options.ControllerVersion.Minor);
                BinaryPrimitives.WriteUInt32BigEndian(version.AsSpan(8), (uint)Math.Max(0, _options.ControllerVersion.Build));
                BinaryPrimitives.WriteUInt32BigEndian(version.AsSpan(12), 0);
                return Rtde.Package(type, version);
            case Rtde.SetupOutputs:
                return SetupOutputs(payload, subscriber, protocol);
            case Rtde.SetupInputs:
                // No inputs are simulated: every name is unknown.
                string names = Encoding.ASCII.GetString(payload);
                return Rtde.Package(type, [0, .. Encoding.ASCII.GetBytes(string.Join(',', names.Split(',').Select(_ => Rtde.NotFound)))]);
            case Rtde.Start:
                bool ok = subscriber.Names.Length > 0 && subscriber.Types.All(t => t != Rtde.NotFound);
                if (ok)
                {
                    lock (_rtdeGate)
                    {
                        _subscribers.Add(subscriber);
                    }
                    WakeRtde();
                }
                return Rtde.Package(type, [ok ? (byte)1 : (byte)0]);
            case Rtde.Pause:
                lock (_rtdeGate)
                {
                    _subscribers.Remove(subscriber);
                }
                return Rtde.Package(type, [1]);
            case Rtde.TextMessage:
                return [];
            default:
                RecordError($"RTDE: unknown package type {type}.");
                return [];
        }
    }

    private byte[] SetupOutputs(ReadOnlySpan<byte> payload, RtdeSubscriber subscriber, ushort protocol)
    {
        double frequency = _options.MaxRtdeFrequency;
        if (protocol == 2)
        {
            if (payload.Length < 8)
            {
                return Rtde.Package(Rtde.SetupOutputs, [0]);
            }
            frequency = BinaryPrimitives.ReadDoubleBigEndian(payload);
            payload = payload[8..];
        }
        string[] names = Encoding.ASCII.GetString(payload).Split(',');
        string[] types = names.Select(TypeOf).ToArray();
        if (!(frequency > 0 && frequency <= _options.MaxRtdeFrequency))
        {
            RecordError($"RTDE: refused an output frequency of {Num.G(frequency)} Hz (1 to {Num.G(_options.MaxRtdeFrequency)}).");
            return Rtde.Package(Rtde.SetupOutputs, [0, .. Encoding.ASCII.GetBytes(string.Join(',', types))]);
        }
        subscriber.Configure(names, types, frequency);
        return Rtde.Package(Rtde.SetupOutputs, [subscriber.RecipeId, .. Encoding.ASCII.GetBytes(string.Join(',', types))]);
    }

    /// <summary>Wakes the RTDE sender: a client started, or the robot's program or safety state changed (reported at once).</summary>
    private void WakeRtde()
    {
        CancellationTokenSource wake;
        lock (_rtdeGate)
        {
            wake = _rtdeWake;
            _rtdeWake = new CancellationTokenSource();
        }
        wake.Cancel();
    }

    /// <summary>
    /// Sends data packages to every started client, each at its own frequency on the controller's clock; a change of program or
    /// safety state is sent to all at once.
    /// </summary>
    private async Task SendRtdeAsync(CancellationToken token)
    {
        bool woken = false;
        while (!token.IsCancellationRequested)
        {
            RtdeSubscriber[] subscribers;
            CancellationToken wake;
            lock (_rtdeGate)
            {
                subscribers = [.. _subscribers];
                wake = _rtdeWake.Token;
            }
            long now = Clock.GetTimestamp();
            TimeSpan wait = TimeSpan.FromSeconds(1);
            foreach (RtdeSubscriber s in subscribers)
            {
                bool due = s.IsDue(Clock, now);
                if (woken || due)
                {
                    if (due)
                    {
                        s.Sent(Clock, now);
                    }
                    if (await s.TrySendAsync(DataPackage(s), token).ConfigureAwait(false))
                    {
                        Interlocked.Increment(ref _rtdePackagesSent);
                    }
                }
                TimeSpan left = s.Period - Clock.GetElapsedTime(s.LastSent, now);
                wait = left < wait ? left : wait;
            }
            woken = false;
            using var both = CancellationTokenSource.CreateLinkedTokenSource(token, wake);
            try
            {
                await Task.Delay(WholeMillisecondsUp(wait), Clock, both.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (!token.IsCancellationRequested)
            {
                woken = true; // a change to report at once
            }
            catch (OperationCanceledException)
            {
                return;
            }
        }
    }

    /// <summary>
    /// A wait rounded up to whole milliseconds (0 for none). Task.Delay counts whole milliseconds and drops the rest: a wait of
    /// 0.7 ms would end at once, before the package is due, and the sender would spin without the clock moving (on a test's
    /// manual clock, forever inside the timer callback that woke it).
    /// </summary>
    internal static TimeSpan WholeMillisecondsUp(TimeSpan wait) =>
        wait > TimeSpan.Zero ? TimeSpan.FromMilliseconds(Math.Ceiling(wait.TotalMilliseconds)) : TimeSpan.Zero;

    /// <summary>One data package of the subscriber's recipe: its id, then each value big-endian in UR's units (m, rad).</summary>
    private byte[] DataPackage(RtdeSubscriber s)
    {
        if (Twin is { } twin)
        {
            return Rtde.Package(Rtde.DataPackage, TwinDataPayload(twin, s.RecipeId, s.Names));
        }
        VirtualUrState state = State;
        int runtime, safety, instance;
        bool registers;
        lock (Gate)
        {
            runtime = (int)_runtime;
            safety = _safety;
            instance = _instanceRegister;
            registers = _kind != DriverKind.Original; // the original driver writes none
        }
        var payload = new byte[1 + s.Types.Sum(Rtde.SizeOf)];
        payload[0] = s.RecipeId;
        int at = 1;
        RotationVector rv = state.Rotation.ToRotationVector();
        double[] pose = [state.Position.X * UrScriptText.Mm, state.Position.Y * UrScriptText.Mm, state.Position.Z * UrScriptText.Mm, rv.X * UrScriptText.Rad, rv.Y * UrScriptText.Rad, rv.Z * UrScriptText.Rad];
        double[] q = [.. Enumerable.Range(0, Joints.Count).Select(i => state.Joints[i] * UrScriptText.Rad)];
        for (int i = 0; i < s.Names.Length; i++)
        {
            Span<byte> to = payload.AsSpan(at);
            switch (s.Names[i])
            {
                case "timestamp":
                    BinaryPrimitives.WriteDoubleBigEndian(to, Clock.GetElapsedTime(0).TotalSeconds);
                    break;
                case "actual_q" or "target_q":
                    WriteVector(to, q);
                    break;
                case "actual_TCP_pose" or "target_TCP_pose":
                    WriteVector(to, pose);
                    break;
                case "actual_qd" or "actual_TCP_speed":
                    WriteVector(to, [0, 0, 0, 0, 0, 0]);
                    break;
                case "robot_mode":
                    BinaryPrimitives.WriteInt32BigEndian(to, 7); // RUNNING
                    break;
                case "safety_mode" or "safety_status":
                    BinaryPrimitives.WriteInt32BigEndian(to, safety);
                    break;
                case "runtime_state":
                    BinaryPrimitives.WriteUInt32BigEndian(to, (uint)runtime);
                    break;
                case "speed_scaling" or "target_speed_fraction":
                    BinaryPrimitives.WriteDoubleBigEndian(to, 1);
                    break;
                case "actual_digital_output_bits":
                    BinaryPrimitives.WriteUInt64BigEndian(to, 0);
                    break;
                default: // output_int_register_N: our driver's progress on 24 and 25, its instance on 26, else 0
                    int register = int.Parse(s.Names[i].AsSpan("output_int_register_".Length), Num.Inv);
                    int value = !registers ? 0 : register switch
                    {
                        UrWire.ExecutedRegister => LastExecutedId,
                        UrWire.ReceivedRegister => LastReceivedId,
                        UrWire.InstanceRegister => instance,
                        _ => 0,
                    };
                    BinaryPrimitives.WriteInt32BigEndian(to, value);
                    break;
            }
            at += Rtde.SizeOf(s.Types[i]);
        }
        return Rtde.Package(Rtde.DataPackage, payload);
    }

    private static void WriteVector(Span<byte> to, ReadOnlySpan<double> values)
    {
        for (int i = 0; i < values.Length; i++)
        {
            BinaryPrimitives.WriteDoubleBigEndian(to[(i * 8)..], values[i]);
        }
    }

    /// <summary>One RTDE client: its output recipe, frequency and when it last got data.</summary>
    private sealed class RtdeSubscriber(NetworkStream stream)
    {
        private readonly SemaphoreSlim _write = new(1, 1);

        public string[] Names { get; private set; } = [];

        public string[] Types { get; private set; } = [];

        public byte RecipeId { get; private set; }

        public TimeSpan Period { get; private set; } = TimeSpan.FromSeconds(1);

        public long LastSent { get; private set; }

        private bool _sentOnce;

        public void Configure(string[] names, string[] types, double frequency)
        {
            Names = names;
            Types = types;
            RecipeId++;
            Period = TimeSpan.FromSeconds(1 / frequency);
        }

        public bool IsDue(TimeProvider clock, long now) => !_sentOnce || clock.GetElapsedTime(LastSent, now) >= Period;

        public void Sent(TimeProvider clock, long now)
        {
            // Keeps the rate exact: the next package is due one period after this one was due, not after it went out.
            LastSent = _sentOnce && clock.GetElapsedTime(LastSent, now) < Period * 2 ? LastSent + Period.Ticks * clock.TimestampFrequency / TimeSpan.TicksPerSecond : now;
            _sentOnce = true;
        }

        public async Task WriteAsync(byte[] bytes, CancellationToken token)
        {
            await _write.WaitAsync(token).ConfigureAwait(false);
            try
            {
                await stream.WriteAsync(bytes, token).ConfigureAwait(false);
            }
            finally
            {
                _write.Release();
            }
        }

        public async Task<bool> TrySendAsync(byte[] bytes, CancellationToken token)
        {
            try
            {
                await WriteAsync(bytes, token).ConfigureAwait(false);
                return true;
            }
            catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
            {
                return false;
            }
        }
    }
}
