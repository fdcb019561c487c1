using System.Globalization;
using System.Net;
using System.Net.Sockets;

namespace Machina.Simulation;

/// <summary>
/// A stand-in for a Universal Robots controller, listening on 127.0.0.1: it runs the URScript programs that arrive on its
/// script port(s) with its interpreter, as a UR does (Machina's driver, the original Machina.NET driver or a compiled
/// program), on a twin arm with the model's kinematics. It serves RTDE (UR's package layout, any RTDE client reads it) and
/// the dashboard commands a host uses, and can be told to enter a protective stop. Made for tests and demos.
/// </summary>
public sealed partial class VirtualUrController : VirtualController<VirtualUrState>
{
    private const int MaxPortAttempts = 50;

    private readonly VirtualUrControllerOptions _options;

    /// <summary>When the controller was made, on the controller's clock: its interfaces' timestamps count from it.</summary>
    private readonly long _bootTimestamp;
    private readonly List<TcpListener> _scriptListeners = [];
    private TcpListener? _rtdeListener;
    private TcpListener? _dashboardListener;

    /// <summary>Creates a stopped controller; call <c>StartAsync</c> to listen.</summary>
    public VirtualUrController(VirtualUrControllerOptions? options = null)
        : this(options ?? new VirtualUrControllerOptions(), 0)
    {
    }

    private VirtualUrController(VirtualUrControllerOptions options, int _)
        : base(options, VirtualUrControllerOptions.DefaultStart, (position, rotation, joints) => new VirtualUrState
        {
            Position = position,
            Rotation = rotation,
            Joints = joints,
            Zone = 5, // the driver's starting blend radius
        })
    {
        _options = options;
        _bootTimestamp = Clock.GetTimestamp();
        _robotMode = options.StartsPoweredOff ? PowerOffMode : RunningMode;
        Twin = CreateTwin();
        _rtdeWait = new VirtualUrDeadlineWait(Clock);
    }

    /// <summary>Time since the controller started, as UR's interfaces stamp their packages (RTDE's <c>timestamp</c>, the client interfaces' time and messages).</summary>
    internal TimeSpan Uptime => Clock.GetElapsedTime(_bootTimestamp);

    /// <summary>The port that takes driver scripts (what a host gives to Connect); 0 until started.</summary>
    public int Port { get; private set; }

    /// <summary>The RTDE port; 0 until started.</summary>
    public int RtdePort { get; private set; }

    /// <summary>The dashboard port; 0 until started.</summary>
    public int DashboardPort { get; private set; }

    private protected override Task ListenAsync(CancellationToken token)
    {
        var (script, rtde, dashboard) = Bind();
        _scriptListeners.Add(script);
        foreach (int extra in _options.ExtraScriptPorts)
        {
            var listener = new TcpListener(IPAddress.Loopback, extra);
            listener.Start();
            _scriptListeners.Add(listener);
        }
        (_rtdeListener, _dashboardListener) = (rtde, dashboard);
        Port = PortOf(script);
        RtdePort = PortOf(rtde);
        DashboardPort = PortOf(dashboard);
        foreach (TcpListener listener in _scriptListeners)
        {
            Run(token => AcceptScriptsAsync(listener, token));
        }
        Run(AcceptRtdeClientsAsync);
        Run(AcceptDashboardClientsAsync);
        Run(SendRtdeAsync);
        ListenClientInterfaces();
        return Task.CompletedTask;
    }

    private protected override void StopListening()
    {
        StopListeners();
        Twin.Dispose(); // stops the running program and closes its sockets
        WakeRtde();
    }

    /// <summary>
    /// As <see cref="StopListening"/>, holding no thread while the running program winds down: awaits the end its thread completes
    /// as its last act (at most the twin's stop timeout, as the join); <paramref name="cancellationToken"/> ends that wait early and
    /// the program is stopped all the same.
    /// </summary>
    private protected override async Task StopListeningAsync(CancellationToken cancellationToken)
    {
        StopListeners();
        Twin.Shutdown(); // what the twin waits for by itself (an RTDE watchdog's stop) ends now: the host's stop is not held by it
        try
        {
            await Twin.StopProgramAsync(cancellationToken).ConfigureAwait(false);
        }
        finally
        {
            Twin.Dispose(); // no program left to join: closes the rest (the RTDE watchdog)
            WakeRtde();
        }
    }

    /// <summary>Stops every listener: the script ports, RTDE, the dashboard and the client interfaces.</summary>
    private void StopListeners()
    {
        foreach (TcpListener listener in _scriptListeners)
        {
            listener.Stop();
        }
        _rtdeListener?.Stop();
        _dashboardListener?.Stop();
        StopClientInterfaces();
    }

    private static int PortOf(TcpListener listener) => ((IPEndPoint)listener.LocalEndpoint).Port;

    /// <summary>The given ports, or three consecutive OS-chosen ones (script, RTDE, dashboard) for those left at 0.</summary>
    private (TcpListener Script, TcpListener RtdeServer, TcpListener DashboardServer) Bind()
    {
        if (_options.ScriptPort != 0 || _options.RtdePort != 0 || _options.DashboardPort != 0)
        {
            return (Listen(_options.ScriptPort), Listen(_options.RtdePort), Listen(_options.DashboardPort));
        }
        for (int attempt = 0; ; attempt++)
        {
            var script = Listen(0);
            int port = PortOf(script);
            if (port + 2 <= IPEndPoint.MaxPort)
            {
                TcpListener? rtde = null;
                try
                {
                    rtde = Listen(port + 1);
                    return (script, rtde, Listen(port + 2));
                }
                catch (SocketException) when (attempt < MaxPortAttempts)
                {
                    rtde?.Stop();
                }
            }
            script.Stop();
            if (attempt >= MaxPortAttempts)
            {
                throw new InvalidOperationException("Could not find three free consecutive ports on 127.0.0.1.");
            }
        }
    }

    private static TcpListener Listen(int port)
    {
        var listener = new TcpListener(IPAddress.Loopback, port);
        listener.Start();
        return listener;
    }

    /// <summary>
    /// The most connections one port of the virtual UR serves at once (dashboard, RTDE, the client interfaces, the script
    /// ports): a client past it is closed at once and the pendant says so (docs/reliability.md, "Connections per port").
    /// </summary>
    internal const int MaxClientsPerPort = 32;

    /// <summary>
    /// Accepts connections from one listener and serves each with <paramref name="serve"/>, one after another or side by side,
    /// at most <see cref="MaxClientsPerPort"/> at once.
    /// </summary>
    private async Task AcceptAsync(TcpListener listener, Func<TcpClient, CancellationToken, Task> serve, CancellationToken token)
    {
        var served = new List<Task>();
        var cap = new Twin.ConnectionCap(MaxClientsPerPort);
        string port = "port " + ((IPEndPoint)listener.LocalEndpoint).Port.ToString(CultureInfo.InvariantCulture);
        while (!token.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await listener.AcceptTcpClientAsync(token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException or InvalidOperationException)
            {
                break;
            }
            served.RemoveAll(t => t.IsCompleted);
            if (!cap.TryEnter())
            {
                Pendant(cap.Refusal(port, client.Client.RemoteEndPoint?.ToString()));
                client.Dispose();
                continue;
            }
            client.NoDelay = true;
            served.Add(ServeCountedAsync(client, serve, cap, token));
        }
        await Task.WhenAll(served).ConfigureAwait(false);
    }

    private static async Task ServeCountedAsync(TcpClient client, Func<TcpClient, CancellationToken, Task> serve, Twin.ConnectionCap cap, CancellationToken token)
    {
        try
        {
            await ServeAsync(client, serve, token).ConfigureAwait(false);
        }
        finally
        {
            cap.Leave();
        }
    }

    private static async Task ServeAsync(TcpClient client, Func<TcpClient, CancellationToken, Task> serve, CancellationToken token)
    {
        using (client)
        {
            try
            {
                await serve(client, token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
            {
                // Client gone or controller stopping.
            }
        }
    }
}
