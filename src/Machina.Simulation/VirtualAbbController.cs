using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation;

/// <summary>
/// A stand-in for an ABB controller running Machina's RAPID driver and monitor, listening on 127.0.0.1.
/// It answers the handshake, executes requests in order with the shared motion model, acknowledges each one
/// after execution, and streams state reports on the monitor port (driver port + 1). Made for tests and demos.
/// </summary>
public sealed partial class VirtualAbbController : VirtualController<VirtualAbbState>
{
    /// <summary>Longest statement read before its ';': 11 numbers and a text of at most 80 characters each, as the RAPID driver reads them.</summary>
    internal const int MaxStatementLength = 14 * 82;

    private readonly VirtualAbbControllerOptions _options;
    private TcpListener? _driverListener;
    private TcpListener? _monitorListener;
    private TimeSpan _monitorPeriod;

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
            ExternalAxesCartesian = options.InitialExternalAxes,
            ExternalAxesJoints = options.InitialExternalAxes,
        })
    {
        _options = options;
        _monitorPeriod = options.MonitorPeriod;
    }

    /// <summary>TCP port of the driver (requests and acknowledgements); 0 until started.</summary>
    public int Port { get; private set; }

    /// <summary>TCP port of the monitor (state reports), always <see cref="Port"/> + 1; 0 until started.</summary>
    public int MonitorPort { get; private set; }

    private protected override Task ListenAsync(CancellationToken token)
    {
        (_driverListener, _monitorListener) = LoopbackPorts.BindPair();
        Port = ((IPEndPoint)_driverListener.LocalEndpoint).Port;
        MonitorPort = Port + 1;
        if (_options.RunsRapid)
        {
            StartTwin(_driverListener, _monitorListener);
            return Task.CompletedTask;
        }
        Run(token => ServeDriverClientsAsync(_driverListener, GreetAsync, ReadRequestsAsync, token));
        Run(token => ServeClientsAsync(_monitorListener, ReportAsync, token));
        return Task.CompletedTask;
    }

    private protected override void StopListening()
    {
        StopTwin();
        _driverListener?.Stop();
        _monitorListener?.Stop();
    }

    /// <summary>The handshake: version, pose, joints, external axes and, from driver 1.6, the progress (<c>$25</c>).</summary>
    private async Task GreetAsync(NetworkStream stream, CancellationToken token)
    {
        VirtualAbbState state = State;
        var version = new AbbDriverVersion(_options.DriverVersion.Major, _options.DriverVersion.Minor, Math.Max(0, _options.DriverVersion.Build));
        var handshake = new List<string>
        {
            AbbMessageFormat.Version(version),
            AbbMessageFormat.Pose(state.Position, state.Rotation),
            AbbMessageFormat.Joints(state.Joints),
            AbbMessageFormat.ExternalAxes(state.ExternalAxesCartesian),
        };
        if (version.ReportsProgress)
        {
            handshake.Add(AbbMessageFormat.Progress(LastExecutedId, LastReceivedId));
        }
        foreach (string message in handshake)
        {
            await stream.WriteAsync(Encoding.ASCII.GetBytes(message), token).ConfigureAwait(false);
        }
    }

    private async Task ReadRequestsAsync(NetworkStream stream, CancellationToken token)
    {
        var bytes = new byte[4096];
        var statement = new StringBuilder();
        try
        {
            while (true)
            {
                int n = await stream.ReadAsync(bytes, token).ConfigureAwait(false);
                if (n == 0)
                {
                    return;
                }
                for (int i = 0; i < n; i++)
                {
                    char c = (char)bytes[i];
                    if (c != ';')
                    {
                        if (statement.Length == MaxStatementLength)
                        {
                            RecordError($"statement longer than {MaxStatementLength} characters without ';': \"{statement.ToString(0, 40)}…\"");
                            return;
                        }
                        statement.Append(c);
                        continue;
                    }
                    string text = statement.ToString();
                    statement.Clear();
                    if (!string.IsNullOrWhiteSpace(text) && !await AcceptStatementAsync(text, token).ConfigureAwait(false))
                    {
                        return;
                    }
                }
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException or System.Threading.Channels.ChannelClosedException)
        {
            // Client gone or controller stopping: like the driver, keep executing what is buffered.
        }
    }

    /// <summary>Parses one statement into the buffer; false when it is malformed (the strict driver would stop).</summary>
    private async Task<bool> AcceptStatementAsync(string text, CancellationToken token)
    {
        if (!AbbRequestParser.TryParse(text, out var request, out string? error))
        {
            RecordError(error!);
            return false;
        }
        await EnqueueAsync(request, request.Id, text.Trim() + ";", token).ConfigureAwait(false);
        return true;
    }
}
