using System.Net;
using System.Net.Sockets;

namespace Machina.Cli.Simulation;

/// <summary>
/// Makes a virtual controller reachable at the address and port a user chose (<c>machina sim --bind --port</c>) when it cannot
/// listen there itself (UR, RWS; ABB and KUKA do, without this hop): listens there and passes bytes both ways to the controller on 127.0.0.1, and logs each connection (what the controller does is told by
/// <see cref="ControllerActivity"/> from the controller itself, not from the bytes: a UR driver script is not a list of requests).
/// </summary>
internal sealed class TcpRelay : IAsyncDisposable
{
    private const int MaxPortAttempts = 50;
    private readonly List<TcpListener> _listeners;
    private readonly Action<string> _log;
    private readonly CancellationTokenSource _stopping = new();
    private readonly List<Task> _tasks = [];
    private readonly Lock _gate = new();
    private readonly List<TcpClient> _clients = [];

    private TcpRelay(List<TcpListener> listeners, Action<string> log)
    {
        _listeners = listeners;
        _log = log;
        Port = ((IPEndPoint)listeners[0].LocalEndpoint).Port;
    }

    /// <summary>The first port listened on (the others follow at the controller's offsets).</summary>
    internal int Port { get; }

    /// <summary>
    /// Listens on <paramref name="address"/> at <paramref name="port"/> (0: the system chooses) plus each route's offset, relaying each
    /// to its controller port on 127.0.0.1. <paramref name="log"/> receives one line per event (thread-safe use is the caller's).
    /// </summary>
    /// <exception cref="CliException">The ports are taken or the address is not on this computer.</exception>
    internal static TcpRelay Start(IPAddress address, int port, IReadOnlyList<RelayRoute> routes, Action<string> log)
    {
        List<TcpListener> listeners = Listen(address, port, [.. routes.Select(r => r.Offset)]);
        var relay = new TcpRelay(listeners, log);
        for (int i = 0; i < listeners.Count; i++)
        {
            RelayRoute route = routes[i];
            TcpListener listener = listeners[i];
            lock (relay._gate)
            {
                relay._tasks.Add(Task.Run(() => relay.AcceptAsync(listener, route.Target, route.Name)));
            }
        }
        return relay;
    }

    /// <summary>Every port listened on, in the order of the routes.</summary>
    internal int[] Ports => [.. _listeners.Select(l => ((IPEndPoint)l.LocalEndpoint).Port)];

    private static List<TcpListener> Listen(IPAddress address, int port, int[] offsets)
    {
        for (int attempt = 0; ; attempt++)
        {
            var listeners = new List<TcpListener>();
            try
            {
                int first = port;
                foreach (int offset in offsets)
                {
                    var listener = new TcpListener(address, first == 0 ? 0 : first + offset);
                    listeners.Add(listener);
                    listener.Start();
                    if (first == 0)
                    {
                        first = ((IPEndPoint)listener.LocalEndpoint).Port;
                    }
                }
                return listeners;
            }
            catch (SocketException ex)
            {
                listeners.ForEach(l => l.Stop());
                if (port == 0 && attempt < MaxPortAttempts && ex.SocketErrorCode == SocketError.AddressAlreadyInUse)
                {
                    continue; // the system's port was free but the next one was not: try another pair
                }
                throw ListenError(ex, address, port, offsets);
            }
        }
    }

    /// <summary>What the command line says when <paramref name="address"/> cannot be listened on at <paramref name="port"/> plus each of <paramref name="offsets"/>.</summary>
    internal static CliException ListenError(SocketException ex, IPAddress address, int port, IEnumerable<int> offsets)
    {
        string ports = string.Join(" and ", offsets.Select(o => (port + o).ToString(System.Globalization.CultureInfo.InvariantCulture)));
        return new CliException(ex.SocketErrorCode == SocketError.AddressAlreadyInUse
            ? $"Port {ports} on {address} is already in use (another controller or program?); choose another with --port."
            : $"Cannot listen on {address} port {ports}: {ex.Message}. Use an address of this computer with --bind (127.0.0.1 by default).");
    }

    /// <summary>
    /// The most connections one relayed port carries at once: a host past it is closed at once and the log says so (each relayed
    /// connection holds two sockets and a connection to the controller; docs/reliability.md, "Connections per port").
    /// </summary>
    internal const int MaxConnectionsPerPort = 32;

    private async Task AcceptAsync(TcpListener listener, int target, string name)
    {
        CancellationToken token = _stopping.Token;
        var cap = new Machina.Simulation.Twin.ConnectionCap(MaxConnectionsPerPort);
        while (!token.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await listener.AcceptTcpClientAsync(token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                return;
            }
            if (!cap.TryEnter())
            {
                _log(cap.Refusal(name, client.Client.RemoteEndPoint?.ToString()));
                client.Dispose();
                continue;
            }
            lock (_gate)
            {
                _tasks.RemoveAll(t => t.IsCompleted); // a long session's connections come and go
                _clients.Add(client);
                _tasks.Add(Task.Run(async () =>
                {
                    try
                    {
                        await ServeAsync(client, target, name, token).ConfigureAwait(false);
                    }
                    finally
                    {
                        cap.Leave();
                    }
                }));
            }
        }
    }

    private async Task ServeAsync(TcpClient client, int target, string what, CancellationToken token)
    {
        string who = client.Client.RemoteEndPoint?.ToString() ?? "a host";
        using var upstream = new TcpClient { NoDelay = true };
        try
        {
            client.NoDelay = true;
            // Connected without the asynchronous engine: a socket that has run one asynchronous operation is read and written through it
            // from then on (on Linux), and the blocking pumps below would wait for its event thread at every read.
            upstream.Connect(IPAddress.Loopback, target);
            _log($"{who} connected ({what})");
            // The sockets themselves: disposing the relay disposes each TcpClient, which forgets its socket.
            Socket host = client.Client ?? throw new ObjectDisposedException(nameof(TcpClient)), controller = upstream.Client;
            var ended = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            using (token.Register(() => ended.TrySetResult()))
            {
                Thread toController = StartPump(host, controller, ended, "relay to controller");
                Thread toHost = StartPump(controller, host, ended, "relay to host");
                await ended.Task.ConfigureAwait(false);
                // Either direction ended (or the relay stops): both connections close, which ends the other pump's blocking read.
                Close(host);
                Close(controller);
                await Task.Run(() =>
                {
                    toController.Join();
                    toHost.Join();
                }).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
        }
        finally
        {
            client.Dispose();
            lock (_gate)
            {
                _clients.Remove(client);
            }
        }
        if (!token.IsCancellationRequested)
        {
            _log($"{who} disconnected ({what})");
        }
    }

    /// <summary>
    /// A thread of its own passing what <paramref name="from"/> receives to <paramref name="to"/> with blocking calls, until either closes;
    /// then <paramref name="ended"/> is set. A blocking read is woken by the kernel itself when data arrives (an awaited read waits for the
    /// runtime's event thread and then for a pool thread: two more threads to wake, each of which may wait for a core while a stream keeps
    /// both busy), and the thread asks for a short time slice (<see cref="Machina.Simulation.VirtualUrRtdeSlice"/>, Linux 6.12 and later)
    /// so that a package passed on at 500 Hz (RTDE) preempts the running thread instead of waiting for its slice to end.
    /// </summary>
    private static Thread StartPump(Socket from, Socket to, TaskCompletionSource ended, string name)
    {
        var thread = new Thread(() =>
        {
            Machina.Simulation.VirtualUrRtdeSlice.Shorten();
            try
            {
                Pump(from, to);
            }
            finally
            {
                ended.TrySetResult();
            }
        })
        { IsBackground = true, Name = name };
        thread.Start();
        return thread;
    }

    private static void Pump(Socket from, Socket to)
    {
        var buffer = new byte[8192];
        try
        {
            while (true)
            {
                // A client that writes with Nagle on (ur_rtde) waits for the acknowledgement of its last small write before the
                // next: acknowledge at once, as the controller's own socket does, not after the kernel's delayed-ACK pause.
                Machina.Simulation.PromptAcknowledgement.BeforeRead(from);
                int n = from.Receive(buffer);
                if (n == 0)
                {
                    return;
                }
                for (int sent = 0; sent < n;)
                {
                    sent += to.Send(buffer, sent, n - sent, SocketFlags.None);
                }
            }
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
        {
        }
    }

    /// <summary>Closes <paramref name="socket"/> both ways (a blocking read of it returns), then frees it.</summary>
    private static void Close(Socket socket)
    {
        try
        {
            socket.Shutdown(SocketShutdown.Both);
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            // already closed
        }
        socket.Dispose();
    }

    /// <summary>Stops listening and closes every relayed connection.</summary>
    public async ValueTask DisposeAsync()
    {
        await _stopping.CancelAsync().ConfigureAwait(false);
        _listeners.ForEach(l => l.Stop());
        Task[] tasks;
        lock (_gate)
        {
            _clients.ForEach(c => c.Dispose());
            tasks = [.. _tasks];
        }
        await Task.WhenAll(tasks).ConfigureAwait(false);
        _stopping.Dispose();
    }
}

/// <summary>One port a <see cref="TcpRelay"/> listens on: its offset from the relay's first port, the controller's port it relays to, and what it is for.</summary>
internal readonly record struct RelayRoute(int Offset, int Target, string Name);
