using System.Buffers.Binary;
using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina;

/// <summary>
/// Host side of the UR link (docs/protocol-ur.md): reads the robot's state over RTDE, opens a server on the local address
/// that reaches the robot (port chosen by the OS), sends Machina's URScript driver once over the script port, and then
/// streams instructions on the connection the script opens back, reading acknowledgements from it.
/// </summary>
internal sealed partial class UrDriver : IDeviceDriver, ILinkReceiver
{
    private readonly DeviceContext _context;
    private readonly RobotLogger _log;
    private readonly TimeProvider _time;
    private readonly AwaitedAcknowledgements _awaiting = new(id => id);
    private readonly TaskCompletionSource<(string Version, int[] Pose)> _handshake = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly UrDriverReader _reader = new();
    private readonly int[] _values = new int[UrActionEncoder.MaxValues];
    private readonly byte[] _encoded = new byte[UrActionEncoder.MaxValues * 4];
    private string _version = "1.2.0";
    private UrPorts _ports;
    private string _host = "";
    private TcpLink? _link;
    private TcpLink? _script;
    private IDeviceListener? _listener;
    private int _failed;

    /// <summary>Creates an unconnected driver for the robot described by <paramref name="context"/>.</summary>
    internal UrDriver(DeviceContext context)
    {
        _context = context;
        _log = context.Logger;
        _time = context.Time;
    }

    /// <inheritdoc/>
    public string RemoteAddress => _link is null ? "" : $"{_host}:{_ports.Script}";

    /// <inheritdoc/>
    public async Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken)
    {
        long start = _time.GetTimestamp();
        _listener = listener;
        _host = host;
        _ports = UrPorts.For(port);
        RtdeSample first = await ConnectRtdeAsync(host, timeout, cancellationToken).ConfigureAwait(false);
        DeviceProgress progress = await SettledProgressAsync(first, Left(start, timeout), cancellationToken).ConfigureAwait(false);

        // The address this computer has on the way to the robot (loopback included), and a port the OS chooses.
        IPAddress local = _rtdeLink!.LocalAddress ?? IPAddress.Loopback;
        if (local.IsIPv4MappedToIPv6)
        {
            local = local.MapToIPv4();
        }
        using var server = new TcpListener(local, 0);
        server.Start();
        int callbackPort = ((IPEndPoint)server.LocalEndpoint).Port;
        _script = await TcpLink.ConnectAsync(host, _ports.Script, Left(start, timeout), _time, cancellationToken).ConfigureAwait(false);
        _script.Start(new Drain());
        _script.Post(Encoding.ASCII.GetBytes(UrDriverScript.For(local.ToString(), callbackPort)));
        _log.Debug($"Sent the UR driver script; it connects back to {local}:{callbackPort}.");

        Socket socket;
        using (var deadline = new CancellationTokenSource(Left(start, timeout), _time))
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
        _link = TcpLink.Adopt(socket, $"{host}:{_ports.Script}");
        _link.Start(this);
        (string version, int[] pose) = await WaitHandshakeAsync(host, Left(start, timeout), cancellationToken).ConfigureAwait(false);
        RtdeSample now = LatestSample ?? first;
        _log.Info($"Connected to the UR driver {version} at {host}; live state over RTDE at {Num.G(_rtdeFrequency)} Hz.");
        return new DeviceHandshake(version, now.Position, now.Rotation, now.Joints, null, progress);
    }

    private async Task<(string Version, int[] Pose)> WaitHandshakeAsync(string host, TimeSpan left, CancellationToken cancellationToken)
    {
        try
        {
            return await _handshake.Task.WaitAsync(left, _time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            throw new RobotConnectionException($"The UR driver program at {host} connected back but did not report its pose in time.");
        }
    }

    private TimeSpan Left(long start, TimeSpan timeout)
    {
        TimeSpan left = timeout - _time.GetElapsedTime(start);
        return left > TimeSpan.Zero ? left : TimeSpan.Zero;
    }

    /// <inheritdoc/>
    public bool Send(RobotAction action, RobotCursor releaseState)
    {
        TcpLink link = _link ?? throw new InvalidOperationException("the link is not open");
        int count = UrActionEncoder.Encode(action, releaseState, _values);
        if (count == 0)
        {
            return false;
        }
        int length = UrWire.Write(_values.AsSpan(0, count), _encoded);
        Adopt(action.Id);
        link.Post(_encoded.AsSpan(0, length));
        return true;
    }

    /// <inheritdoc/>
    public int WireId(int actionId) => actionId;

    /// <inheritdoc/>
    public void Adopt(int actionId)
    {
        _awaiting.Expect(actionId);
    }

    /// <inheritdoc/>
    public void OnReceived(ReadOnlySpan<byte> data)
    {
        try
        {
            while (Volatile.Read(ref _failed) == 0 && _reader.TryRead(ref data, out int acknowledged, out int[]? response))
            {
                if (response is not null)
                {
                    OnResponse(response);
                }
                else
                {
                    Acknowledge(acknowledged);
                }
            }
        }
        catch (RobotConnectionException e)
        {
            Fail(e);
        }
    }

    private void OnResponse(int[] response)
    {
        switch (response[0])
        {
            case UrWire.ResponseVersion when response.Length == 4:
                _version = $"{response[1]}.{response[2]}.{response[3]}";
                break;
            case UrWire.ResponseFullPose when response.Length == 13:
                _handshake.TrySetResult((_version, response[1..]));
                break;
            default:
                _log.Debug($"Ignored a response from the UR driver: {string.Join(' ', response)}");
                break;
        }
    }

    private void Acknowledge(int id)
    {
        int actionId = _awaiting.Resolve(id);
        _listener?.OnAcknowledged(actionId);
    }

    /// <inheritdoc/>
    public void OnClosed(Exception? error) => Fail(error is null
        ? new RobotConnectionException("The UR driver program closed the connection.")
        : new RobotConnectionException($"The connection to the UR driver program failed: {error.Message}", error));

    private void Fail(MachinaException error)
    {
        if (Interlocked.Exchange(ref _failed, 1) != 0)
        {
            return;
        }
        if (!_handshake.Task.IsCompleted)
        {
            _handshake.TrySetException(error);
        }
        else
        {
            _listener?.OnFault(error);
        }
    }

    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        Interlocked.Exchange(ref _failed, 1);
        foreach (TcpLink? link in new[] { _rtdeLink, _script, _link })
        {
            if (link is not null)
            {
                await link.DisposeAsync().ConfigureAwait(false);
            }
        }
    }

    /// <summary>Reads and drops what the script port sends (the controller's state stream), so its buffers never fill (fix of U1).</summary>
    private sealed class Drain : ILinkReceiver
    {
        public void OnReceived(ReadOnlySpan<byte> data)
        {
        }

        public void OnClosed(Exception? error)
        {
        }
    }
}
