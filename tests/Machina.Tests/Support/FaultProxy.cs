using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;

namespace Machina.Tests.Support;

/// <summary>What a <see cref="FaultProxy"/> does to the bytes it carries; every choice is drawn from <see cref="Seed"/>.</summary>
internal sealed record FaultProxyOptions
{
    /// <summary>Seed of every random choice (per connection: the seed, the channel and the connection's number).</summary>
    public int Seed { get; init; }

    /// <summary>Which of the proxied ports (0 = the first) the closing and garbage faults apply to.</summary>
    public int FaultChannel { get; init; }

    /// <summary>Close this many of the fault channel's connections, each after a seeded number of bytes towards the host. Default 0.</summary>
    public int CloseConnections { get; init; }

    /// <summary>
    /// The ranges the number of bytes before a close or the garbage is drawn from (towards the host, counted from the
    /// connection's start): the first for the fault channel's first connection, the second for its second, and so on; the
    /// last range serves every later connection.
    /// </summary>
    public IReadOnlyList<(int Min, int Max)> CloseAfterBytes { get; init; } = [(100, 400)];

    /// <summary>Inject garbage towards the host on this many of the fault channel's connections, after a seeded number of bytes (same range). Default 0.</summary>
    public int GarbageConnections { get; init; }

    /// <summary>The garbage injected.</summary>
    public byte[] Garbage { get; init; } = "#garbage;"u8.ToArray();

    /// <summary>Each chunk, in either direction, waits a seeded time from 0 to this before it is written (order is kept). Default none.</summary>
    public TimeSpan MaxDelay { get; init; }

    /// <summary>Write every byte on its own, in both directions, on every channel. Default false.</summary>
    public bool SplitIntoBytes { get; init; }

    /// <summary>
    /// Hold the bytes towards the controller on this many of the fault channel's first connections, from
    /// <see cref="HoldAfterBytes"/> on, until <see cref="FaultProxy.ReleaseHeldAsync"/>: a slow link that still delivers them
    /// after the host has given up (the controller side stays open until then). Default 0.
    /// </summary>
    public int HoldConnections { get; init; }

    /// <summary>
    /// Every fault-channel connection can be held later: <see cref="FaultProxy.HoldNow"/> holds what follows on the live ones,
    /// <see cref="FaultProxy.HoldNext"/> the next ones from their first byte. Default false.
    /// </summary>
    public bool Holdable { get; init; }

    /// <summary>Bytes that pass before a held connection starts holding. Default 0 (hold everything).</summary>
    public int HoldAfterBytes { get; init; }

    /// <summary>
    /// Hold the bytes towards the side that connected instead (for a proxy a controller connects through, e.g. a UR driver
    /// program calling the host back: the host's instructions to it). Default false.
    /// </summary>
    public bool HoldTowardsConnector { get; init; }
}

/// <summary>
/// A loopback TCP proxy between a host and a controller, on consecutive OS-chosen ports mirroring the controller's (so a
/// host finds a monitor at port + 1, RTDE and dashboard at + 1 and + 2). It closes connections, delays bytes, splits writes
/// into single bytes and injects garbage towards the host, deterministically from a seed. Every wait is bounded; dispose it
/// at the end of the test (it closes everything and waits for its loops).
/// </summary>
internal sealed partial class FaultProxy : IAsyncDisposable
{
    private const int MaxPortAttempts = 50;
    private static readonly TimeSpan StopLimit = TimeSpan.FromSeconds(10);

    private readonly FaultProxyOptions _options;
    private readonly TcpListener[] _listeners;
    private readonly int[] _targets; // a channel's target can change (Retarget) before its next connection
    private readonly CancellationTokenSource _stopping = new();
    private readonly ConcurrentBag<TcpClient> _sockets = [];
    private readonly List<Task> _loops = [];
    private readonly object _gate = new();
    private int _faultConnections;
    private readonly List<long> _towardsHost = [];
    private int _closed;
    private int _garbage;
    private int _accepted;
    private readonly int[] _acceptedOn;

    private FaultProxy(FaultProxyOptions options, TcpListener[] listeners, int[] targets)
    {
        _options = options;
        _listeners = listeners;
        _targets = targets;
        _acceptedOn = new int[listeners.Length];
        for (int i = 0; i < listeners.Length; i++)
        {
            int channel = i;
            _loops.Add(Task.Run(() => AcceptAsync(channel)));
        }
    }

    /// <summary>The first port (a host connects here); the others follow it.</summary>
    public int Port => ((IPEndPoint)_listeners[0].LocalEndpoint).Port;

    /// <summary>Connections accepted on all channels.</summary>
    public int Accepted => Volatile.Read(ref _accepted);

    /// <summary>Connections accepted on one channel (0 = the first port).</summary>
    public int AcceptedOn(int channel) => Volatile.Read(ref _acceptedOn[channel]);

    /// <summary>Connections the proxy closed as a fault.</summary>
    public int Closed => Volatile.Read(ref _closed);

    /// <summary>Bytes carried towards the host by each finished connection of the fault channel, in the order they ended.</summary>
    public IReadOnlyList<long> BytesTowardsHost
    {
        get
        {
            lock (_gate)
            {
                return [.. _towardsHost];
            }
        }
    }

    /// <summary>Times garbage was injected.</summary>
    public int GarbageInjected => Volatile.Read(ref _garbage);

    /// <summary>Points <paramref name="channel"/> at another port from its next connection on (a port the other side chooses late).</summary>
    public void Retarget(int channel, int port) => Volatile.Write(ref _targets[channel], port);

    /// <summary>Starts a proxy for the controller ports <paramref name="targetPorts"/> (consecutive on the proxy side too).</summary>
    public static FaultProxy Start(IReadOnlyList<int> targetPorts, FaultProxyOptions options)
    {
        ArgumentOutOfRangeException.ThrowIfZero(targetPorts.Count);
        return new FaultProxy(options, BindConsecutive(targetPorts.Count), [.. targetPorts]);
    }

    private static TcpListener[] BindConsecutive(int count)
    {
        for (int attempt = 0; ; attempt++)
        {
            var first = new TcpListener(IPAddress.Loopback, 0);
            first.Start();
            int port = ((IPEndPoint)first.LocalEndpoint).Port;
            var listeners = new List<TcpListener> { first };
            try
            {
                for (int i = 1; i < count; i++)
                {
                    var next = new TcpListener(IPAddress.Loopback, port + i);
                    next.Start();
                    listeners.Add(next);
                }
                return [.. listeners];
            }
            catch (SocketException) when (attempt < MaxPortAttempts)
            {
                listeners.ForEach(l => l.Stop());
            }
        }
    }

    private async Task AcceptAsync(int channel)
    {
        var token = _stopping.Token;
        var served = new List<Task>();
        int number = 0;
        while (!token.IsCancellationRequested)
        {
            TcpClient host;
            try
            {
                host = await _listeners[channel].AcceptTcpClientAsync(token);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                break;
            }
            Interlocked.Increment(ref _accepted);
            Interlocked.Increment(ref _acceptedOn[channel]);
            served.Add(ServeAsync(host, channel, number++, token));
        }
        await Task.WhenAll(served);
    }

    private async Task ServeAsync(TcpClient host, int channel, int number, CancellationToken token)
    {
        var controller = new TcpClient { NoDelay = true };
        host.NoDelay = true;
        _sockets.Add(host);
        _sockets.Add(controller);
        try
        {
            using var connect = CancellationTokenSource.CreateLinkedTokenSource(token);
            connect.CancelAfter(StopLimit);
            await controller.ConnectAsync(IPAddress.Loopback, Volatile.Read(ref _targets[channel]), connect.Token);
        }
        catch (Exception e) when (e is SocketException or OperationCanceledException or ObjectDisposedException)
        {
            host.Dispose();
            controller.Dispose();
            return;
        }
        // Not HashCode.Combine: its results change from one process to the next.
        int seed = unchecked(_options.Seed * 7919 + channel * 104_729 + number * 1_299_709);
        int faultNumber = -1;
        if (channel == _options.FaultChannel)
        {
            lock (_gate)
            {
                faultNumber = _faultConnections++;
            }
        }
        var random = new Random(seed);
        var (min, max) = _options.CloseAfterBytes[Math.Clamp(faultNumber, 0, _options.CloseAfterBytes.Count - 1)];
        int closeAt = faultNumber >= 0 && faultNumber < _options.CloseConnections ? random.Next(min, max + 1) : -1;
        int garbageAt = faultNumber >= 0 && faultNumber < _options.GarbageConnections ? random.Next(min, max + 1) : -1;
        using var both = CancellationTokenSource.CreateLinkedTokenSource(token);
        bool held = faultNumber >= 0 && (faultNumber < _options.HoldConnections || _options.Holdable);
        long holdAt = held && (faultNumber < _options.HoldConnections || TakeNextHold()) ? _options.HoldAfterBytes : long.MaxValue;
        HeldLink? hold = !held ? null : _options.HoldTowardsConnector ? AddHeld(controller, host, holdAt) : AddHeld(host, controller, holdAt);
        Task<long> up = hold is not null && !_options.HoldTowardsConnector
            ? hold.PumpAsync(both.Token)
            : PumpAsync(host, controller, new Random(seed + 1), -1, -1, both.Token);
        Task<long> down = hold is not null && _options.HoldTowardsConnector
            ? hold.PumpAsync(both.Token)
            : PumpAsync(controller, host, new Random(seed + 2), closeAt, garbageAt, both.Token);
        Task first = await Task.WhenAny(up, down);
        if (hold is not null && hold.Holding)
        {
            // The sender is gone and the receiver still listens: what the link holds arrives when the test releases it.
            await (_options.HoldTowardsConnector ? down : up);
        }
        await both.CancelAsync();
        host.Dispose();
        controller.Dispose();
        await Task.WhenAll(up, down);
        if (faultNumber >= 0)
        {
            lock (_gate)
            {
                _towardsHost.Add(down.Result);
            }
        }
    }

    /// <summary>Copies bytes one way until either side ends, applying the faults; never throws. Returns how many it carried.</summary>
    private async Task<long> PumpAsync(TcpClient from, TcpClient to, Random random, int closeAt, int garbageAt, CancellationToken token)
    {
        var buffer = new byte[4096];
        long carried = 0;
        try
        {
            var input = from.GetStream();
            var output = to.GetStream();
            while (true)
            {
                int n = await input.ReadAsync(buffer, token);
                if (n == 0)
                {
                    return carried;
                }
                if (_options.MaxDelay > TimeSpan.Zero)
                {
                    await Task.Delay(TimeSpan.FromTicks((long)(random.NextDouble() * _options.MaxDelay.Ticks)), token);
                }
                for (int i = 0; i < n; i++)
                {
                    if (carried == garbageAt)
                    {
                        await output.WriteAsync(_options.Garbage, token);
                        Interlocked.Increment(ref _garbage);
                    }
                    if (carried == closeAt)
                    {
                        Interlocked.Increment(ref _closed);
                        return carried;
                    }
                    int run = _options.SplitIntoBytes ? 1 : RunLength(carried, n - i, closeAt, garbageAt);
                    await output.WriteAsync(buffer.AsMemory(i, run), token);
                    carried += run;
                    i += run - 1;
                }
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            // One side left, or the proxy stops.
        }
        return carried;
    }

    /// <summary>How many bytes can go in one write before the next fault point.</summary>
    private static int RunLength(long carried, int left, int closeAt, int garbageAt)
    {
        long run = left;
        foreach (int at in (int[])[closeAt, garbageAt])
        {
            if (at > carried)
            {
                run = Math.Min(run, at - carried);
            }
        }
        return (int)run;
    }

    public async ValueTask DisposeAsync()
    {
        await _stopping.CancelAsync();
        ReleaseOnStop();
        foreach (TcpListener listener in _listeners)
        {
            listener.Stop();
        }
        foreach (TcpClient socket in _sockets)
        {
            socket.Dispose();
        }
        try
        {
            await Task.WhenAll(_loops).WaitAsync(StopLimit);
        }
        catch (TimeoutException)
        {
            Assert.Fail("The fault proxy's loops did not stop within " + StopLimit);
        }
        _stopping.Dispose();
    }
}
