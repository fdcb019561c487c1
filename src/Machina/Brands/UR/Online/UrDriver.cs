using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina;

/// <summary>
/// Host side of the UR link (docs/protocol-ur.md): reads the robot's state over RTDE, opens a server on the local address
/// that reaches the robot (port chosen by the OS), sends Machina's URScript driver once over the script port, and then
/// streams instructions on the connection the script opens back, reading acknowledgements from it.
/// </summary>
internal sealed partial class UrDriver : DeviceDriver<UrReply>, IDeviceDriver
{
    private readonly DeviceContext _context;
    private string _version = "";

    /// <summary>The last read value response (id, value × FactorAnalog), handed over with the acknowledgement of that id.</summary>
    private (int Id, int Raw)? _read;
    private UrPorts _ports;
    private string _host = "";

    /// <summary>Creates an unconnected driver for the robot described by <paramref name="context"/>.</summary>
    internal UrDriver(DeviceContext context)
        : base(context.Logger, context.Time, new UrDriverReader(), "UR driver program")
    {
        _context = context;
    }

    /// <summary>
    /// How long the driver program waits for an instruction's values after its header before it takes its stream as broken
    /// (<see cref="UrDriverScript.DefaultValuesTimeout"/>; tests shorten it).
    /// </summary>
    internal TimeSpan ValuesTimeout { get; init; } = UrDriverScript.DefaultValuesTimeout;

    /// <inheritdoc/>
    public override string RemoteAddress => Link is null ? "" : $"{_host}:{_ports.Script}";

    /// <inheritdoc/>
    protected override async Task<DeviceHandshake> OpenAsync(string host, int port, TimeSpan timeout, CancellationToken cancellationToken)
    {
        long start = Time.GetTimestamp();
        _host = host;
        _ports = UrPorts.For(port);
        RtdeSample first = await ConnectRtdeAsync(host, timeout, cancellationToken).ConfigureAwait(false);
        // Which arm this is, from the dashboard server (at most half the time left: it never fails the connection).
        (string? Name, RobotModel? Model) arm = await ReadModelAsync(Left(start, timeout) / 2, cancellationToken).ConfigureAwait(false);
        // At most half the time: an old program stuck inside an instruction (its link cut mid-way) must not starve the connect.
        await SettleAsync(Left(start, timeout) / 2, cancellationToken).ConfigureAwait(false);

        // The address this computer has on the way to the robot (loopback included), and a port the OS chooses.
        IPAddress local = _rtdeLink!.LocalAddress ?? IPAddress.Loopback;
        if (local.IsIPv4MappedToIPv6)
        {
            local = local.MapToIPv4();
        }
        using var server = new TcpListener(local, 0);
        server.Start();
        int callbackPort = ((IPEndPoint)server.LocalEndpoint).Port;
        // What the script port sends is read (its buffers never fill, fix of U1) for the runtime errors that stop a program.
        TcpLink script = await OpenSideLinkAsync(host, _ports.Script, Left(start, timeout), new UrRobotMessage.Reader(OnRuntimeException), cancellationToken).ConfigureAwait(false);
        script.Post(Encoding.ASCII.GetBytes(UrDriverScript.For(local.ToString(), callbackPort, _instance, ValuesTimeout)));
        Log.Debug($"Sent the UR driver script (instance {_instance}); it connects back to {local}:{callbackPort}.");

        Socket socket;
        using (var deadline = new CancellationTokenSource(Left(start, timeout), Time))
        using (var both = CancellationTokenSource.CreateLinkedTokenSource(deadline.Token, cancellationToken))
        {
            try
            {
                socket = await server.AcceptSocketAsync(both.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
            {
                throw new RobotConnectionException(
                    $"The UR controller at {host} took the driver script but its program did not connect back to {local}:{callbackPort} within {Num.G(timeout.TotalSeconds)} s. Is the robot powered on and in remote control, and can it reach this computer?");
            }
        }
        StartLink(TcpLink.Adopt(socket, $"{host}:{_ports.Script}"));
        DeviceHandshake driver = await HandshakeAsync(Left(start, timeout),
            () => $"The UR driver program at {host} connected back but did not report its pose in time.", cancellationToken).ConfigureAwait(false);
        Requirement.Check(driver.Version);
        DeviceProgress progress = await ProgressOfAsync(_instance, Left(start, timeout), cancellationToken).ConfigureAwait(false);
        RtdeSample now = LatestSample ?? first;
        Log.Info($"Connected to the UR driver {driver.Version} at {host}; live state over RTDE at {Num.G(_rtdeFrequency)} Hz.");
        return new DeviceHandshake(driver.Version, now.Position, now.Rotation, now.Joints, null, progress) { ModelName = arm.Name, Model = arm.Model };
    }

    /// <summary>
    /// The URScript driver this host needs: the one it sends (drivers/ur), whose wire carries 0.001 mm and 1e-6 rad (3.0; 2.x
    /// carried 0.1 mm and 1e-4 rad, which this host would misread a hundredfold).
    /// </summary>
    internal static DriverRequirement Requirement { get; } = new("UR", Version.Parse(UrDriverScript.Version),
        "This Machina sends its own driver program on every connection, so another program connected back in its place: is another Machina driving this robot? Stop it, then connect again.");

    /// <inheritdoc/>
    public int WireId(int actionId) => actionId;

    /// <inheritdoc/>
    /// <remarks>The session keeps what is in flight and maps the ids; this driver keeps only the last id it sent, to tell at a close whether anything was in flight.</remarks>
    public void Adopt(int actionId) => Sent(actionId);

    /// <inheritdoc/>
    protected override void OnMessage(in UrReply reply)
    {
        if (reply.Response is int[] response)
        {
            OnResponse(response);
        }
        else
        {
            Acknowledge(reply.Acknowledged);
        }
    }

    private void OnResponse(int[] response)
    {
        switch (response[0])
        {
            case UrWire.ResponseVersion when response.Length == 4:
                _version = $"{response[1]}.{response[2]}.{response[3]}";
                break;
            case UrWire.ResponseInput when response.Length == 3:
                _read = (response[1], response[2]);
                break;
            case UrWire.ResponseFullPose when response.Length == 13:
                Handshake(new DeviceHandshake(_version, null, null, null, null)); // the pose comes from RTDE
                break;
            default:
                Log.Debug($"Ignored a response from the UR driver: {string.Join(' ', response)}");
                break;
        }
    }

    private void Acknowledge(int id)
    {
        Acknowledged(id);
        if (_read is (int readId, int raw) && readId == id)
        {
            // Digital and analog values alike travel × FactorAnalog (a digital input: 0 or 1,000,000).
            _read = null;
            Listener?.OnAcknowledged(id, raw / UrWire.FactorAnalog);
            return;
        }
        Listener?.OnAcknowledged(id);
    }
}
