using System.Net;
using System.Net.Sockets;

namespace Machina.Bridge;

/// <summary>
/// The Machina Bridge: a WebSocket server that streams the instructions its clients send (Grasshopper, Dynamo, Processing,
/// Python, JavaScript, or the page it serves at <c>/</c>) to one robot, and sends every client the robot's events as JSON.
/// It drives a real controller, or a virtual one started inside the bridge. Start it with <see cref="StartAsync"/>, stop
/// it with <see cref="StopAsync"/> or <see cref="DisposeAsync"/>.
/// </summary>
public sealed partial class BridgeServer : IAsyncDisposable
{
    private readonly BridgeOptions _options;
    private readonly FrameHandler _frames;
    private readonly byte[] _page;
    private readonly object _gate = new();
    private readonly List<Task> _connections = [];
    private readonly LinkedList<CancellationTokenSource> _handshakes = new();
    private BridgeClient[] _clients = [];
    private TcpListener? _listener;
    private CancellationTokenSource? _stopping;
    private Task? _acceptLoop;
    private EmbeddedController? _embedded;
    private Task? _reconnecting;
    private string? _lastMotion;
    private string? _lastArm;
    private int _connectionCount; // WebSocket clients holding a slot (see BridgeOptions.MaxConnections)
    private int _state; // 0 new, 1 starting or running, 2 stopped

    /// <summary>Creates a stopped bridge and its robot (see <see cref="Robot"/>); nothing listens until <see cref="StartAsync"/>.</summary>
    /// <exception cref="ArgumentException">A setting in <paramref name="options"/> cannot work; the message says which.</exception>
    public BridgeServer(BridgeOptions? options = null)
    {
        _options = options ?? new BridgeOptions();
        _options.Validate();
        Robot = _options.RobotFactory is { } factory
            ? factory() ?? throw new ArgumentException("The robot factory returned null.", nameof(options))
            : Robot.Create(_options.RobotName, _options.Brand);
        _frames = new FrameHandler(Robot, () => Robot.IsConnected);
        _page = BridgePage.Render(_options.Path);
    }

    /// <summary>How long a client may take to answer the close frame when the bridge stops or the client leaves (tests shorten it).</summary>
    internal TimeSpan CloseTimeout { get; set; } = TimeSpan.FromSeconds(5);

    /// <summary>The settings this bridge was made with.</summary>
    public BridgeOptions Options => _options;

    /// <summary>
    /// The one robot this bridge drives. Its <see cref="Robot.Logger"/> also reports what the bridge does (clients coming and
    /// going, refused messages). A host may issue actions on it too: their events go to every client, as in the original.
    /// </summary>
    public Robot Robot { get; }

    /// <summary>The address and port the bridge listens on, once started (the port the system chose when the options said 0).</summary>
    public IPEndPoint? LocalEndpoint { get; private set; }

    /// <summary>The port the bridge listens on; 0 until started.</summary>
    public int Port => LocalEndpoint?.Port ?? 0;

    /// <summary>The address clients connect to, e.g. <c>ws://127.0.0.1:6999/Bridge</c>; null until started.</summary>
    public Uri? WebSocketUri => LocalEndpoint is { } e ? new Uri($"ws://{HostText(e)}{_options.Path}") : null;

    /// <summary>The address of the bridge's page, e.g. <c>http://127.0.0.1:6999/</c>; null until started.</summary>
    public Uri? PageUri => LocalEndpoint is { } e ? new Uri($"http://{HostText(e)}/") : null;

    /// <summary>The loopback port of the virtual controller inside the bridge, or null when it drives a real controller (or is not started).</summary>
    public int? SimulatorPort => _embedded?.Port;

    /// <summary>The virtual controller inside the bridge (the brand's own controller object; tests pause and resume it), or null.</summary>
    internal IAsyncDisposable? Simulator => _embedded?.Owner;

    /// <summary>How many connections are in their HTTP handshake now (tests watch it).</summary>
    internal int PendingHandshakeCount
    {
        get
        {
            lock (_gate)
            {
                return _handshakes.Count;
            }
        }
    }

    /// <summary>How many WebSocket clients are connected now.</summary>
    public int ClientCount
    {
        get
        {
            lock (_gate)
            {
                return _clients.Length;
            }
        }
    }

    /// <summary>
    /// Listens, connects the robot to its controller (starting the virtual one first when no controller host is set), and
    /// then accepts clients. Everything started is stopped again when this fails.
    /// </summary>
    /// <exception cref="SocketException">The address cannot be listened on (the port may be taken by another program).</exception>
    /// <exception cref="MachinaException">The controller could not be reached or did not answer as expected.</exception>
    /// <exception cref="NotSupportedException">There is no virtual controller (or no online control) for the robot's brand yet.</exception>
    /// <exception cref="InvalidOperationException">The bridge was already started.</exception>
    public async Task StartAsync(CancellationToken cancellationToken = default)
    {
        if (Interlocked.CompareExchange(ref _state, 1, 0) != 0)
        {
            throw new InvalidOperationException("This bridge was already started; create a new one.");
        }
        _stopping = new CancellationTokenSource();
        try
        {
            _listener = new TcpListener(_options.Listen);
            _listener.Start();
            LocalEndpoint = (IPEndPoint)_listener.LocalEndpoint;
            await ConnectRobotAsync(cancellationToken).ConfigureAwait(false);
        }
        catch
        {
            await StopAsync().ConfigureAwait(false);
            throw;
        }
        CancellationToken stop = _stopping.Token;
        _acceptLoop = Task.Run(() => AcceptLoopAsync(stop), CancellationToken.None);
        if (!IPAddress.IsLoopback(LocalEndpoint.Address))
        {
            Robot.Logger.Warning($"Bridge: listening on {LocalEndpoint}, which other computers can reach; anyone who can connect can move the robot.");
        }
        Robot.Logger.Info($"Bridge: clients connect to {WebSocketUri}; the page is at {PageUri}");
    }

    private async Task ConnectRobotAsync(CancellationToken cancellationToken)
    {
        string host;
        int port;
        if (_options.ControllerHost is { } realHost)
        {
            (host, port) = (realHost, _options.ControllerPort);
        }
        else
        {
            var start = EmbeddedControllers.For(Robot.Brand) ?? throw new NotSupportedException(
                $"The bridge has no virtual controller for {Robot.Brand} robots yet; connect to a real controller with a host and port instead.");
            _embedded = await start(_options, cancellationToken).ConfigureAwait(false);
            (host, port) = ("127.0.0.1", _embedded.Port);
            // No model is set here: the robot learns the arm when it connects, from the virtual controller as from a real one
            // (docs/online.md), so a joint move has a known pose and a client's MoveTo after an AxesTo is not refused.
        }
        Robot.ControlMode(ControlType.Online);
        Subscribe();
        await Robot.ConnectAsync(host, port, cancellationToken).ConfigureAwait(false);
        Robot.Logger.Info(_embedded is null
            ? $"Bridge: connected to the {Robot.Brand} controller at {host}:{port}."
            : $"Bridge: connected to a virtual {Robot.Brand} controller{(Robot.Model is { } m ? $" ({m})" : "")} (speed ×{_options.SimulationSpeed}).");
    }

    /// <summary>
    /// Closes every client (after sending what was queued for it, at most a few seconds), stops listening, disconnects the
    /// robot and stops the virtual controller. Safe to call more than once.
    /// </summary>
    public async Task StopAsync()
    {
        if (Interlocked.Exchange(ref _state, 2) == 2 || _stopping is null)
        {
            return;
        }
        await _stopping.CancelAsync().ConfigureAwait(false);
        _listener?.Stop();
        if (_acceptLoop is not null)
        {
            await _acceptLoop.ConfigureAwait(false);
        }
        BridgeClient[] clients;
        Task[] connections;
        lock (_gate)
        {
            clients = _clients;
            connections = [.. _connections];
        }
        foreach (BridgeClient client in clients)
        {
            client.Close(System.Net.WebSockets.WebSocketCloseStatus.EndpointUnavailable, "The bridge is stopping.");
        }
        try
        {
            await Task.WhenAll(connections).WaitAsync(CloseTimeout, _options.TimeProvider).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            // A client that does not answer the close frame is dropped.
            foreach (BridgeClient client in clients)
            {
                client.Abort();
            }
            await Task.WhenAll(connections).ConfigureAwait(false);
        }
        Unsubscribe();
        if (_reconnecting is { } reconnecting)
        {
            await reconnecting.ConfigureAwait(false);
        }
        await Robot.DisconnectAsync().ConfigureAwait(false);
        if (_embedded is not null)
        {
            try
            {
                await _embedded.Owner.DisposeAsync().ConfigureAwait(false);
            }
            catch (Exception e)
            {
                // Stopping always completes; a virtual controller that failed earlier reports its failure here (logged).
                Robot.Logger.Error($"Bridge: the virtual controller had failed: {e.GetType().Name}: {e.Message}");
            }
        }
        _stopping.Dispose();
    }

    /// <summary>Same as <see cref="StopAsync"/>.</summary>
    public async ValueTask DisposeAsync() => await StopAsync().ConfigureAwait(false);

    private static string HostText(IPEndPoint endpoint) =>
        endpoint.AddressFamily == AddressFamily.InterNetworkV6 ? $"[{endpoint.Address}]:{endpoint.Port}" : $"{endpoint.Address}:{endpoint.Port}";
}
