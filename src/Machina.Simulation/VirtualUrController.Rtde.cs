using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;
using Packages = Machina.Simulation.VirtualUrRtdePackages;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    private readonly List<RtdeSubscriber> _subscribers = [];
    private readonly Lock _rtdeGate = new();
    private readonly VirtualUrDeadlineWait _rtdeWait;
    private int _rtdePackagesSent;

    /// <summary>How many RTDE data packages have been sent, to all clients.</summary>
    public int RtdePackagesSent => Volatile.Read(ref _rtdePackagesSent);

    /// <summary>The type of an RTDE output name, or <c>NOT_FOUND</c>.</summary>
    internal static string TypeOf(string name) => VirtualUrRtdeFields.OutputType(name);

    private Task AcceptRtdeClientsAsync(CancellationToken token) => AcceptAsync(_rtdeListener!, ServeRtdeAsync, token);

    /// <summary>One RTDE client: version negotiation, controller version, output setup, start and pause; data goes out from <see cref="SendRtdeAsync"/>.</summary>
    private async Task ServeRtdeAsync(TcpClient client, CancellationToken token)
    {
        var stream = client.GetStream();
        var subscriber = new RtdeSubscriber(stream, Clock.TimestampFrequency);
        var reader = new VirtualUrRtdeReader();
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
                    if (type == Packages.Start && reply[^1] == 1)
                    {
                        // Data only after the start's answer, as on a UR: a client that skips what comes before it loses none.
                        lock (_rtdeGate)
                        {
                            if (!_subscribers.Contains(subscriber))
                            {
                                _subscribers.Add(subscriber);
                            }
                        }
                        WakeRtde();
                    }
                }
            }
        }
        catch (InvalidDataException e)
        {
            RecordError("RTDE: " + e.Message);
        }
        finally
        {
            lock (_rtdeGate)
            {
                _subscribers.Remove(subscriber);
            }
            ReleaseInputs(subscriber);
        }
    }

    /// <summary>The reply package to one request (empty for none).</summary>
    private byte[] Answer(byte type, ReadOnlySpan<byte> payload, RtdeSubscriber subscriber, ref ushort protocol)
    {
        switch (type)
        {
            case Packages.RequestProtocolVersion:
                ushort asked = payload.Length >= 2 ? BinaryPrimitives.ReadUInt16BigEndian(payload) : (ushort)0;
                bool accepted = asked is 1 or 2;
                if (accepted)
                {
                    protocol = asked;
                }
                return Packages.Package(type, [accepted ? (byte)1 : (byte)0]);
            case Packages.GetControllerVersion:
                var version = new byte[16];
                BinaryPrimitives.WriteUInt32BigEndian(version, (uint)_options.ControllerVersion.Major);
                BinaryPrimitives.WriteUInt32BigEndian(version.AsSpan(4), (uint)_options.ControllerVersion.Minor);
                BinaryPrimitives.WriteUInt32BigEndian(version.AsSpan(8), (uint)Math.Max(0, _options.ControllerVersion.Build));
                BinaryPrimitives.WriteUInt32BigEndian(version.AsSpan(12), 0);
                return Packages.Package(type, version);
            case Packages.SetupOutputs:
                return SetupOutputs(payload, subscriber, protocol);
            case Packages.SetupInputs:
                return SetupInputs(payload, subscriber);
            case Packages.DataPackage:
                ApplyInputs(payload, subscriber);
                return [];
            case Packages.Start:
                bool ok = (subscriber.Names.Length > 0 && subscriber.Types.All(t => t != Packages.NotFound)) || subscriber.HasInputs;
                return Packages.Package(type, [ok ? (byte)1 : (byte)0]);
            case Packages.Pause:
                lock (_rtdeGate)
                {
                    _subscribers.Remove(subscriber);
                }
                return Packages.Package(type, [1]);
            case Packages.TextMessage:
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
                return Packages.Package(Packages.SetupOutputs, [0]);
            }
            frequency = BinaryPrimitives.ReadDoubleBigEndian(payload);
            payload = payload[8..];
        }
        string[] names = VirtualUrRtdeFields.Recipe(Encoding.ASCII.GetString(payload));
        string[] types = names.Select(TypeOf).ToArray();
        if (!(frequency > 0 && frequency <= _options.MaxRtdeFrequency))
        {
            RecordError($"RTDE: refused an output frequency of {Num.G(frequency)} Hz (1 to {Num.G(_options.MaxRtdeFrequency)}).");
            return Packages.Package(Packages.SetupOutputs, [0, .. Encoding.ASCII.GetBytes(string.Join(',', types))]);
        }
        subscriber.Configure(names, types, frequency);
        return Packages.Package(Packages.SetupOutputs, [subscriber.RecipeId, .. Encoding.ASCII.GetBytes(string.Join(',', types))]);
    }

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
        bool woken = false;
        try
        {
            while (!token.IsCancellationRequested)
            {
                RtdeSubscriber[] subscribers;
                lock (_rtdeGate)
                {
                    subscribers = [.. _subscribers];
                }
                long now = Clock.GetTimestamp();
                long next = now + Clock.TimestampFrequency; // a second when no client is started
                foreach (RtdeSubscriber s in subscribers)
                {
                    bool due = s.IsDue(now);
                    if (woken || due)
                    {
                        if (due)
                        {
                            s.Sent(now);
                        }
                        if (s.TrySend(DataPackage(s), token))
                        {
                            Interlocked.Increment(ref _rtdePackagesSent);
                        }
                    }
                    next = Math.Min(next, s.NextDue(now));
                }
                woken = _rtdeWait.WaitUntil(next, token);
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

    /// <summary>One data package of the subscriber's recipe: its id, then each value big-endian in UR's units (m, rad).</summary>
    private byte[] DataPackage(RtdeSubscriber s) => Packages.Package(Packages.DataPackage, TwinDataPayload(Twin, s.RecipeId, s.Names));

    /// <summary>One RTDE client: its output recipe, frequency and when it last got data.</summary>
    private sealed class RtdeSubscriber(NetworkStream stream, long timestampFrequency)
    {
        private readonly SemaphoreSlim _write = new(1, 1);

        public string[] Names { get; private set; } = [];

        public string[] Types { get; private set; } = [];

        public byte RecipeId { get; private set; }

        /// <summary>When the last package was due (a timestamp of the controller's clock).</summary>
        public long LastSent { get; private set; }

        private bool _sentOnce;

        /// <summary>How far behind its deadlines a client may fall and still get every package (sent back to back); past that it starts again from now.</summary>
        private const int CatchUpPeriods = 10;

        public void Configure(string[] names, string[] types, double frequency)
        {
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
        public bool IsDue(long now) => !_sentOnce || now - LastSent >= _periodTicks;

        /// <summary>When the next package is due.</summary>
        public long NextDue(long now) => _sentOnce ? LastSent + _periodTicks : now;

        /// <summary>A package went out at <paramref name="now"/>.</summary>
        public void Sent(long now)
        {
            // Keeps the rate exact: the next package is due one period after this one was due, not after it went out.
            LastSent = _sentOnce && (now - LastSent) / CatchUpPeriods < _periodTicks ? LastSent + _periodTicks : now;
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

        /// <summary>Writes a data package from the sender's thread; false when the client has gone.</summary>
        public bool TrySend(byte[] bytes, CancellationToken token)
        {
            try
            {
                _write.Wait(token);
                try
                {
                    stream.Write(bytes);
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
