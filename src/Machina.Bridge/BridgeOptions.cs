using System.Net;

namespace Machina.Bridge;

/// <summary>Settings of a <see cref="BridgeServer"/>. Every property has a usable default: a simulated ABB robot served on 127.0.0.1:6999.</summary>
public sealed record BridgeOptions
{
    /// <summary>The port the original Machina Bridge listened on, and the default here.</summary>
    public const int DefaultPort = 6999;

    /// <summary>The URL path of the WebSocket, as the original clients use it (<c>ws://127.0.0.1:6999/Bridge</c>).</summary>
    public const string DefaultPath = "/Bridge";

    /// <summary>Address and port to listen on. Default 127.0.0.1:6999 (this computer only). Port 0 lets the system choose one (see <see cref="BridgeServer.Port"/>).</summary>
    public IPEndPoint Listen { get; init; } = new(IPAddress.Loopback, DefaultPort);

    /// <summary>URL path of the WebSocket (default <c>/Bridge</c>, any letter case). The page is served at <c>/</c>.</summary>
    public string Path { get; init; } = DefaultPath;

    /// <summary>Name of the robot the bridge creates (ignored when <see cref="RobotFactory"/> is set).</summary>
    public string RobotName { get; init; } = "Bridge";

    /// <summary>Brand of the robot the bridge creates (ignored when <see cref="RobotFactory"/> is set). Default ABB.</summary>
    public RobotType Brand { get; init; } = BrandRegistry.DefaultOnline.Type;

    /// <summary>Makes the robot, instead of <see cref="RobotName"/> and <see cref="Brand"/>; the bridge switches it online and connects it.</summary>
    public Func<Robot>? RobotFactory { get; init; }

    /// <summary>
    /// Address of the real controller running Machina's driver. Null (the default) starts a virtual controller inside the bridge
    /// instead, so that everything can be tried without a robot.
    /// </summary>
    public string? ControllerHost { get; init; }

    /// <summary>Port of the driver on the real controller (default 7000). Not used with the virtual controller.</summary>
    public int ControllerPort { get; init; } = 7000;

    /// <summary>How much faster than real time the virtual controller runs motions and waits (default 1, real time).</summary>
    public double SimulationSpeed { get; init; } = 1;

    /// <summary>
    /// Web pages allowed to connect from a browser, as origins such as <c>http://localhost:8080</c>; <c>*</c> allows any.
    /// The bridge's own page and clients that send no origin (Grasshopper, Dynamo, Python, Processing, Node) are always allowed.
    /// Empty by default, so a web site you visit cannot drive the robot.
    /// </summary>
    public IReadOnlyList<string> AllowedOrigins { get; init; } = [];

    /// <summary>Largest message a client may send, in bytes (default 1 MiB: tens of thousands of instructions). Larger ones are refused with an error event.</summary>
    public int MaxMessageBytes { get; init; } = 1024 * 1024;

    /// <summary>How many WebSocket clients may be connected at once (default 64); more are answered with HTTP 503.</summary>
    public int MaxConnections { get; init; } = 64;

    /// <summary>
    /// How many events may wait for a slow client (default 250 000, enough for the <c>action-issued</c> of a largest message);
    /// a client that falls further behind is disconnected, so that it cannot hold up the robot or the others.
    /// </summary>
    public int MaxQueuedEvents { get; init; } = 250_000;

    /// <summary>How long a new connection may take to send its HTTP request and finish the handshake (default 10 s).</summary>
    public TimeSpan RequestTimeout { get; init; } = TimeSpan.FromSeconds(10);

    /// <summary>
    /// How many connections may be in their handshake at once (default 128). They do not count against <see cref="MaxConnections"/>;
    /// when one more arrives, the oldest of them is dropped, so that slow or idle connections cannot lock clients out.
    /// </summary>
    public int MaxPendingHandshakes { get; init; } = 128;

    /// <summary>
    /// A secret that clients must pass in their address as <c>authkey=</c> (e.g. <c>ws://127.0.0.1:6999/Bridge?authkey=…</c>), or null
    /// (the default) for none. Required when <see cref="Listen"/> is not a loopback address, since other computers can then connect.
    /// </summary>
    public string? Token { get; init; }

    /// <summary>Clock for the timeouts above and for the virtual controller; tests may replace it.</summary>
    public TimeProvider TimeProvider { get; init; } = TimeProvider.System;

    /// <summary>Throws <see cref="ArgumentException"/> explaining the first setting that cannot work.</summary>
    internal void Validate()
    {
        ArgumentNullException.ThrowIfNull(Listen, nameof(Listen));
        ArgumentNullException.ThrowIfNull(TimeProvider, nameof(TimeProvider));
        ArgumentNullException.ThrowIfNull(AllowedOrigins, nameof(AllowedOrigins));
        if (string.IsNullOrEmpty(Path) || Path[0] != '/' || Path.Any(c => c is '?' or '#' or ' ' || char.IsControl(c)))
        {
            throw new ArgumentException($"The WebSocket path must start with '/' and hold no spaces, '?' or '#', such as \"{DefaultPath}\"; it was \"{Path}\".", nameof(Path));
        }
        if (ControllerHost is not null && string.IsNullOrWhiteSpace(ControllerHost))
        {
            throw new ArgumentException("The controller host is blank; give its address, or leave it null to use the virtual controller.", nameof(ControllerHost));
        }
        if (ControllerPort is < 1 or > 65535)
        {
            throw new ArgumentOutOfRangeException(nameof(ControllerPort), ControllerPort, "The controller port must be between 1 and 65535.");
        }
        if (!(SimulationSpeed > 0) || !double.IsFinite(SimulationSpeed))
        {
            throw new ArgumentOutOfRangeException(nameof(SimulationSpeed), SimulationSpeed, "The simulation speed must be a positive number (1 is real time).");
        }
        if (MaxMessageBytes < 1024)
        {
            throw new ArgumentOutOfRangeException(nameof(MaxMessageBytes), MaxMessageBytes, "Messages of at least 1024 bytes must be allowed.");
        }
        if (MaxConnections < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(MaxConnections), MaxConnections, "At least one connection must be allowed.");
        }
        if (MaxQueuedEvents < 16)
        {
            throw new ArgumentOutOfRangeException(nameof(MaxQueuedEvents), MaxQueuedEvents, "At least 16 events must be allowed to wait for a client.");
        }
        if (MaxPendingHandshakes < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(MaxPendingHandshakes), MaxPendingHandshakes, "At least one connection must be allowed to shake hands.");
        }
        if (Token is not null && (Token.Length < 8 || Token.Any(c => c <= ' ' || c >= '\x7f' || c is '&' or '#' or '%' or '+')))
        {
            throw new ArgumentException("The token must be at least 8 printable ASCII characters without spaces, '&', '#', '%' or '+', so that it can be written in an address as is.", nameof(Token));
        }
        if (Token is null && !IPAddress.IsLoopback(Listen.Address))
        {
            throw new ArgumentException($"Listening on {Listen.Address} lets other computers connect, so a token is required: give one (machina bridge --token …) that clients pass as authkey=….", nameof(Token));
        }
        if (RequestTimeout <= TimeSpan.Zero)
        {
            throw new ArgumentOutOfRangeException(nameof(RequestTimeout), RequestTimeout, "The request timeout must be positive.");
        }
    }
}
