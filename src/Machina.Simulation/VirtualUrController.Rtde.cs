using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;
using Packages = Machina.Simulation.VirtualUrRtdePackages;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>The started clients: replaced whole under <see cref="_rtdeGate"/>, read by the sender without it.</summary>
    private RtdeSubscriber[] _subscribers = [];
    private readonly Lock _rtdeGate = new();
    private readonly VirtualUrDeadlineWait _rtdeWait;
    private int _rtdePackagesSent;

    /// <summary>How many RTDE data packages have been sent, to all clients.</summary>
    public int RtdePackagesSent => Volatile.Read(ref _rtdePackagesSent);

    /// <summary>The type of an RTDE output name, or <c>NOT_FOUND</c>.</summary>
    internal static string TypeOf(string name) => VirtualUrRtdeFields.OutputType(name);

    private Task AcceptRtdeClientsAsync(CancellationToken token) => AcceptAsync(_rtdeListener!, ServeRtdeAsync, token);

    /// <summary>
    /// One RTDE client on a thread of its own: version negotiation, controller version, output and input setup, input data,
    /// start and pause; output data goes out from <see cref="SendRtdeAsync"/>. Blocking reads: a package is handled as soon as
    /// its thread wakes, where an awaited read also waits for a pool thread to take it up (on a loaded machine, milliseconds).
    /// </summary>
    private Task ServeRtdeAsync(TcpClient client, CancellationToken token) =>
        Task.Factory.StartNew(() => ServeRtde(client, token), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);

    private void ServeRtde(TcpClient client, CancellationToken token)
    {
        client.SendTimeout = ClientSendTimeoutMs; // a client that stops reading is dropped (SendRtde), not waited for by every other
        var stream = client.GetStream();
        using CancellationTokenRegistration stopping = token.Register(stream.Dispose); // the controller stops: the read ends
        var subscriber = new RtdeSubscriber(stream, Clock.TimestampFrequency, (long)(_rtdeWait.Early.TotalSeconds * Clock.TimestampFrequency));
        var reader = new VirtualUrRtdeReader(stream);
        var reply = new VirtualUrRtdeWriter(64);
        ushort protocol = 1;
        try
        {
            // Each package acknowledged as it is read: ur_rtde writes two input packages back to back with Nagle's algorithm on.
            while (ReadAcknowledged(client.Client, reader) is byte type)
            {
                if (!Answer(type, reader.Payload, subscriber, reply, ref protocol))
                {
                    continue;
                }
                ReadOnlyMemory<byte> answer = reply.End();
                if (!subscriber.TrySend(answer, token))
                {
                    return;
                }
                if (type == Packages.Start && answer.Span[^1] == 1)
                {
                    // Data only after the start's answer, as on a UR: a client that skips what comes before it loses none.
                    lock (_rtdeGate)
                    {
                        if (!_subscribers.Contains(subscriber))
                        {
                            Volatile.Write(ref _subscribers, [.. _subscribers, subscriber]);
                        }
                    }
                    WakeRtde();
                }
            }
        }
        catch (InvalidDataException e)
        {
            RecordError("RTDE: " + e.Message);
        }
        finally
        {
            Unsubscribe(subscriber);
            ReleaseInputs(subscriber);
        }
    }

    private static byte? ReadAcknowledged(Socket socket, VirtualUrRtdeReader reader)
    {
        PromptAcknowledgement.BeforeRead(socket);
        return reader.Read();
    }

    /// <summary>Stops sending data to a client (a pause, or it left).</summary>
    private void Unsubscribe(RtdeSubscriber subscriber)
    {
        lock (_rtdeGate)
        {
            Volatile.Write(ref _subscribers, [.. _subscribers.Where(s => s != subscriber)]);
        }
    }

    /// <summary>Writes the reply package to one request into <paramref name="reply"/>; false for none.</summary>
    private bool Answer(byte type, ReadOnlySpan<byte> payload, RtdeSubscriber subscriber, VirtualUrRtdeWriter reply, ref ushort protocol)
    {
        reply.Begin(type);
        switch (type)
        {
            case Packages.RequestProtocolVersion:
                ushort asked = payload.Length >= 2 ? BinaryPrimitives.ReadUInt16BigEndian(payload) : (ushort)0;
                bool accepted = asked is 1 or 2;
                if (accepted)
                {
                    protocol = asked;
                }
                reply.Byte(accepted ? (byte)1 : (byte)0);
                return true;
            case Packages.GetControllerVersion: // the version every interface reports (3.15.8 for a CB-Series arm)
                Version version = SoftwareVersion;
                reply.UInt32((uint)version.Major);
                reply.UInt32((uint)version.Minor);
                reply.UInt32((uint)Math.Max(0, version.Build));
                reply.UInt32(0);
                return true;
            case Packages.SetupOutputs:
                SetupOutputs(payload, subscriber, protocol, reply);
                return true;
            case Packages.SetupInputs:
                SetupInputs(payload, subscriber, reply);
                return true;
            case Packages.DataPackage:
                ApplyInputs(payload, subscriber);
                return false;
            case Packages.Start:
                bool ok = (subscriber.Names.Length > 0 && subscriber.Types.All(t => t != Packages.NotFound)) || subscriber.HasInputs;
                reply.Byte(ok ? (byte)1 : (byte)0);
                return true;
            case Packages.Pause:
                Unsubscribe(subscriber);
                reply.Byte(1);
                return true;
            case Packages.TextMessage:
                ShowClientMessage(payload);
                return false;
            default:
                RecordError($"RTDE: unknown package type {type}.");
                return false;
        }
    }

    /// <summary>Output setup: the recipe's types with its id, or id 0 when the frequency is refused or the data package would be too long to frame.</summary>
    private void SetupOutputs(ReadOnlySpan<byte> payload, RtdeSubscriber subscriber, ushort protocol, VirtualUrRtdeWriter reply)
    {
        double frequency = MaxRtdeFrequency;
        if (protocol == 2)
        {
            if (payload.Length < 8)
            {
                reply.Byte(0);
                return;
            }
            frequency = BinaryPrimitives.ReadDoubleBigEndian(payload);
            payload = payload[8..];
        }
        string[] names = VirtualUrRtdeFields.Recipe(Encoding.ASCII.GetString(payload));
        string[] types = names.Select(TypeOf).ToArray();
        int size = Packages.HeaderSize + 1 + types.Sum(Packages.SizeOf);
        byte id = 0;
        if (!(frequency > 0 && frequency <= MaxRtdeFrequency))
        {
            RecordError($"RTDE: refused an output frequency of {Num.G(frequency)} Hz (1 to {Num.G(MaxRtdeFrequency)}).");
        }
        else if (size > Packages.MaxSize)
        {
            RecordError($"RTDE: refused an output recipe whose data package would be {size} bytes (at most {Packages.MaxSize}).");
        }
        else
        {
            subscriber.Configure(names, types, frequency, size);
            id = subscriber.RecipeId;
        }
        reply.Byte(id);
        reply.Ascii(string.Join(',', types));
    }

    /// <summary>The highest output frequency of the software the controller reports: 500 Hz from software 5 (e-Series), 125 Hz before.</summary>
    private double MaxRtdeFrequency => SoftwareVersion.Major >= 5 ? 500 : 125;

    /// <summary>How long the RTDE sender waits while no client is started: until a client's start wakes it, in effect (seconds).</summary>
    private const long IdleWaitSeconds = 3600;

    /// <summary>Wakes the RTDE sender: a client started, or the robot's program or safety state changed (reported at once).</summary>
    private void WakeRtde() => _rtdeWait.Wake();

    /// <summary>The RTDE sender on a thread of its own (a pool thread's timer wake-ups cost 1–2 ms a tick: issue 45).</summary>
    private Task SendRtdeAsync(CancellationToken token) =>
        Task.Factory.StartNew(() => SendRtde(token), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);

    /// <summary>
    /// Sends data packages to every started client, each at its own frequency on the controller's clock, on deadlines counted
    /// from the first package (a late package does not move the next one); a change of program or safety state is sent to all
    /// at once.
    /// </summary>
    private void SendRtde(CancellationToken token)
    {
        _rtdeWait.OnWaitingThread();
        bool woken = false, collected = false;
        var snapshot = new RtdeSnapshot(this);
        using VirtualUrRtdeTiming? timing = VirtualUrRtdeTiming.FromEnvironment(Clock.TimestampFrequency, _rtdeWait.Precise);
        try
        {
            while (!token.IsCancellationRequested)
            {
                // A wake before this look (a client started before the sender's first round) is served by it, to every client as
                // any wake is; one after it ends the wait below. Without this, a client started before the sender's first round
                // got a second package of the same tick (UrSimWatchdogTests counted 5 packages for 4 once in CI).
                woken |= _rtdeWait.TakeWake();
                RtdeSubscriber[] subscribers = Volatile.Read(ref _subscribers);
                long now = Clock.GetTimestamp();
                // No client started: nothing is due until one starts, and its start wakes this wait (WakeRtde); an hour stands for
                // "until woken" (a second here woke an idle twin's sender twice a second: the wait and its final stretch).
                long next = now + Clock.TimestampFrequency * IdleWaitSeconds;
                snapshot.Clear();
                foreach (RtdeSubscriber s in subscribers)
                {
                    bool due = s.IsDue(now);
                    if (woken || due)
                    {
                        if (due)
                        {
                            timing?.Record(now - s.NextDue(now), collected);
                            s.Sent(now);
                        }
                        // Counted before it goes out, so that a client that has read a package sees it in the count (a test
                        // read the count just after its last package and found one short once in CI); a send that fails takes it back.
                        Interlocked.Increment(ref _rtdePackagesSent);
                        if (!s.TrySend(DataPackage(s, snapshot), token))
                        {
                            Interlocked.Decrement(ref _rtdePackagesSent);
                            Unsubscribe(s);
                            s.Close(); // gone, or it stopped reading: its connection ends
                        }
                    }
                    next = Math.Min(next, s.NextDue(now));
                }
                TimeSpan pause = timing is null ? default : VirtualUrRtdeTiming.PauseNow;
                woken = _rtdeWait.WaitUntil(next, token);
                if (timing is not null)
                {
                    collected = VirtualUrRtdeTiming.PauseNow != pause;
                    if (woken)
                    {
                        timing.Woken();
                    }
                }
            }
        }
        catch (OperationCanceledException)
        {
        }
    }

    /// <summary>
    /// A wait rounded up to whole milliseconds (0 for none). Task.Delay counts whole milliseconds and drops the rest: a wait of
    /// 0.7 ms would end at once, before the package is due, and the sender would spin without the clock moving (on a test's
    /// manual clock, forever inside the timer callback that woke it).
    /// </summary>
    internal static TimeSpan WholeMillisecondsUp(TimeSpan wait) =>
        wait > TimeSpan.Zero ? TimeSpan.FromMilliseconds(Math.Ceiling(wait.TotalMilliseconds)) : TimeSpan.Zero;

    /// <summary>
    /// One data package of the subscriber's recipe, written into its own buffer (sent before the next is written): its id, then
    /// each value big-endian in UR's units (m, rad).
    /// </summary>
    private ReadOnlyMemory<byte> DataPackage(RtdeSubscriber s, RtdeSnapshot snapshot)
    {
        VirtualUrRtdeWriter data = s.Data;
        data.Begin(Packages.DataPackage);
        data.Byte(s.RecipeId);
        WriteOutputs(Twin, data, s.Names, snapshot);
        return data.End();
    }

    /// <summary>
    /// What one tick of the sender reports, taken when a package first needs it and kept for every client of that tick: the
    /// controller's time, and the state of the arm, program and I/O (forward kinematics and a read of every signal, which a
    /// recipe of time and registers does without).
    /// </summary>
    private sealed class RtdeSnapshot(VirtualUrController controller)
    {
        private double? _time;
        private VirtualUrClientState? _state;

        /// <summary>Controller time, seconds.</summary>
        public double Time => _time ??= controller.Uptime.TotalSeconds;

        /// <summary>The controller's state this tick.</summary>
        public VirtualUrClientState State => _state ??= controller.ClientState();

        /// <summary>A new tick: nothing taken yet.</summary>
        public void Clear()
        {
            _time = null;
            _state = null;
        }
    }

    /// <summary>
    /// One RTDE client: its output recipe, frequency and when it last got data. A package counts as due
    /// <paramref name="earlyTicks"/> before its deadline (the sender's wait ends that early rather than spin for the rest).
    /// </summary>
    private sealed class RtdeSubscriber(NetworkStream stream, long timestampFrequency, long earlyTicks)
    {
        private readonly SemaphoreSlim _write = new(1, 1);

        public string[] Names { get; private set; } = [];

        /// <summary>The writer of this client's data packages, used by the sender's thread only.</summary>
        public VirtualUrRtdeWriter Data { get; private set; } = new(1);

        public string[] Types { get; private set; } = [];

        public byte RecipeId { get; private set; }

        /// <summary>When the last package was due (a timestamp of the controller's clock).</summary>
        public long LastSent { get; private set; }

        private bool _sentOnce;

        /// <summary>How far behind its deadlines a client may fall and still get every package (sent back to back); past that it starts again from now.</summary>
        private const int CatchUpPeriods = 10;

        public void Configure(string[] names, string[] types, double frequency, int packageSize)
        {
            Data = new VirtualUrRtdeWriter(packageSize - VirtualUrRtdePackages.HeaderSize);
            Names = names;
            Types = types;
            RecipeId = ++_lastOutputRecipe;
            _periodTicks = Math.Max(1, (long)Math.Round(timestampFrequency / frequency));
        }

        private byte _lastOutputRecipe, _lastInputRecipe;

        /// <summary>
        /// The next input recipe id of this connection. Inputs count from 1 apart from outputs, as a UR does: ur_rtde sends its
        /// input data under ids 1, 2, 3… in the order it set the input recipes up, after setting up its output recipe.
        /// </summary>
        public byte NextInputRecipe() => ++_lastInputRecipe;

        /// <summary>The input recipes of this connection by id: names and types.</summary>
        public Dictionary<byte, (string[] Names, string[] Types)> InputRecipes { get; } = [];

        /// <summary>The last value this client sent for each input name (masks apply with the last value sent).</summary>
        public Dictionary<string, double> InputValues { get; } = new(StringComparer.Ordinal);

        /// <summary>True when an input recipe has been set up.</summary>
        public bool HasInputs => InputRecipes.Count > 0;

        private long _periodTicks = long.MaxValue / 4; // until configured: never due again after the first

        /// <summary>True when a package is due at <paramref name="now"/>: the first at once, then one each period.</summary>
        public bool IsDue(long now) => !_sentOnce || now - LastSent >= _periodTicks - earlyTicks;

        /// <summary>When the next package is due.</summary>
        public long NextDue(long now) => _sentOnce ? LastSent + _periodTicks : now;

        /// <summary>A package went out at <paramref name="now"/>.</summary>
        public void Sent(long now)
        {
            // Keeps the rate exact: the next package is due one period after this one was due, not after it went out.
            LastSent = _sentOnce && (now - LastSent) / CatchUpPeriods < _periodTicks ? LastSent + _periodTicks : now;
            _sentOnce = true;
        }

        /// <summary>Closes the connection (its reads end too).</summary>
        public void Close() => stream.Dispose();

        /// <summary>Writes a data package from the sender's thread; false when the client has gone or stopped reading (the send timed out).</summary>
        public bool TrySend(ReadOnlyMemory<byte> bytes, CancellationToken token)
        {
            try
            {
                if (!_write.Wait(ClientSendTimeoutMs, token))
                {
                    return false; // a reply has been stuck that long: the client stopped reading
                }
                try
                {
                    stream.Write(bytes.Span);
                }
                finally
                {
                    _write.Release();
                }
                return true;
            }
            catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
            {
                return false;
            }
        }
    }
}
