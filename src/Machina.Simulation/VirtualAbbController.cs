using System.Net;
using System.Net.Sockets;

namespace Machina.Simulation;

/// <summary>
/// A stand-in for an ABB controller running Machina's RAPID driver and monitor, listening on 127.0.0.1: a RAPID interpreter runs the
/// unchanged modules of drivers/abb in two tasks, as an IRC5 would, on the robot model of the options. The driver task answers the
/// handshake, executes requests in order and acknowledges each one after execution; the monitor task streams state reports on the
/// monitor port (driver port + 1). Made for tests and demos.
/// </summary>
public sealed partial class VirtualAbbController : VirtualController<VirtualAbbState>
{
    private readonly VirtualAbbControllerOptions _options;
    private TcpListener? _driverListener;
    private TcpListener? _monitorListener;

    /// <summary>Creates a stopped controller; call <c>StartAsync</c> to listen.</summary>
    public VirtualAbbController(VirtualAbbControllerOptions? options = null)
        : this(options ?? new VirtualAbbControllerOptions(), 0)
    {
    }

    private VirtualAbbController(VirtualAbbControllerOptions options, int _)
        : base(options, VirtualAbbControllerOptions.DefaultStart, (position, rotation, joints) => new VirtualAbbState
        {
            Position = position,
            Rotation = rotation,
            Joints = joints,
            Zone = 5,
            ExternalAxesCartesian = ExternalAxes.None,
            ExternalAxesJoints = ExternalAxes.None,
        })
    {
        _options = options;
        _connections = new ConnectionLog(options.ConnectionSeen);
    }

    /// <summary>TCP port of the driver (requests and acknowledgements); 0 until started.</summary>
    public int Port { get; private set; }

    /// <summary>TCP port of the monitor (state reports), always <see cref="Port"/> + 1; 0 until started.</summary>
    public int MonitorPort { get; private set; }

    private protected override Task ListenAsync(CancellationToken token)
    {
        (_driverListener, _monitorListener) = LoopbackPorts.BindPair(_options.ListenAddress, _options.ListenPort);
        Port = ((IPEndPoint)_driverListener.LocalEndpoint).Port;
        MonitorPort = Port + 1;
        StartTwin(_driverListener, _monitorListener);
        return Task.CompletedTask;
    }

    private protected override void StopListening()
    {
        StopTwin();
        _driverListener?.Stop();
        _monitorListener?.Stop();
    }
}
