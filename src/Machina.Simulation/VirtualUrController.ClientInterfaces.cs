using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>How long a client interface waits for a client to take a package before it drops that client.</summary>
    private const int ClientSendTimeoutMs = 2000;

    private readonly VirtualUrClientGroup<ClientConnection> _primaryClients = new();
    private readonly VirtualUrClientGroup<ClientConnection> _realtimeClients = new();
    private readonly List<TcpListener> _clientListeners = [];
    private VirtualUrArmFacts? _armFacts;

    /// <summary>The primary client interface port (a UR: 30001), or 0 when not served or not started.</summary>
    public int PrimaryPort { get; private set; }

    /// <summary>The secondary client interface port (a UR: 30002), or 0 when not served or not started.</summary>
    public int SecondaryPort { get; private set; }

    /// <summary>The real-time client interface port (a UR: 30003), or 0 when not served or not started.</summary>
    public int RealtimePort { get; private set; }

    /// <summary>How many clients the real-time interface has now.</summary>
    internal int RealtimeClients => _realtimeClients.Count;

    /// <summary>Starts the client interfaces the options ask for.</summary>
    private void ListenClientInterfaces()
    {
        _armFacts = VirtualUrArmFacts.Of(Model ?? RobotModels.Get("UR5e"));
        if (_options.PrimaryPort is int primary)
        {
            PrimaryPort = ListenClients(primary, (c, t) => ServeStateClientAsync(c, primary: true, t));
        }
        if (_options.SecondaryPort is int secondary)
        {
            SecondaryPort = ListenClients(secondary, (c, t) => ServeStateClientAsync(c, primary: false, t));
        }
        if (_options.RealtimePort is int realtime)
        {
            RealtimePort = ListenClients(realtime, ServeRealtimeClientAsync);
        }
        if (_options.PrimaryPort is not null || _options.SecondaryPort is not null)
        {
            Run(token => SendClientPackagesAsync(_primaryClients, TimeSpan.FromMilliseconds(100), () => VirtualUrClientPackages.State(ClientState(), _armFacts), token));
        }
        if (_options.RealtimePort is not null)
        {
            double rate = SoftwareVersion.Major >= 5 ? 500 : 125;
            Run(token => SendClientPackagesAsync(_realtimeClients, TimeSpan.FromSeconds(1 / rate), () => VirtualUrClientPackages.Realtime(ClientState(), SoftwareVersion), token));
        }
    }

    private int ListenClients(int port, Func<TcpClient, CancellationToken, Task> serve)
    {
        TcpListener listener = Listen(port);
        _clientListeners.Add(listener);
        Run(token => AcceptAsync(listener, serve, token));
        return PortOf(listener);
    }

    private void StopClientInterfaces()
    {
        foreach (TcpListener listener in _clientListeners)
        {
            listener.Stop();
        }
    }

    /// <summary>
    /// A primary or secondary client: the version message first, then robot state at 10 Hz and robot messages (text, runtime
    /// exceptions); what it sends is URScript, and on the primary port also the controller's primary commands.
    /// </summary>
    private async Task ServeStateClientAsync(TcpClient client, bool primary, CancellationToken token)
    {
        var connection = new ClientConnection(client);
        connection.Send(VirtualUrClientPackages.Version(Timestamp, SoftwareVersion));
        connection.Send(VirtualUrClientPackages.State(ClientState(), _armFacts!));
        _primaryClients.Add(connection);
        try
        {
            await FeedTwinAsync(client.GetStream(), Twin, token, primary).ConfigureAwait(false);
        }
        finally
        {
            _primaryClients.Remove(connection);
        }
    }

    /// <summary>A real-time client: the real-time package at the controller's rate; what it sends is URScript.</summary>
    private async Task ServeRealtimeClientAsync(TcpClient client, CancellationToken token)
    {
        var connection = new ClientConnection(client);
        _realtimeClients.Add(connection);
        try
        {
            await FeedTwinAsync(client.GetStream(), Twin, token).ConfigureAwait(false);
        }
        finally
        {
            _realtimeClients.Remove(connection);
        }
    }

    /// <summary>A primary command: power, brakes, protective stop, program stop (awaited: a stop holds no thread while the program ends).</summary>
    private async Task PrimaryCommandAsync(string command, CancellationToken token)
    {
        Pendant("Primary interface: " + command);
        switch (command)
        {
            case "power on":
                PowerOn();
                break;
            case "power off":
                await PowerOffAsync(token).ConfigureAwait(false);
                break;
            case "set robotmode run":
                ReleaseBrakes();
                break;
            case "set unlock protective stop":
                UnlockProtectiveStop();
                break;
            default: // stop program
                await StopTwinAsync(Twin, token).ConfigureAwait(false);
                break;
        }
    }

    /// <summary>
    /// Sends a fresh package to every client of one interface each period, while it has clients; without one it runs no timer
    /// (<see cref="VirtualUrClientGroup{T}"/>) and starts again, on the period from then, when one connects.
    /// </summary>
    private async Task SendClientPackagesAsync(VirtualUrClientGroup<ClientConnection> clients, TimeSpan period, Func<byte[]> package, CancellationToken token)
    {
        try
        {
            while (true)
            {
                await clients.UntilAnyAsync(token).ConfigureAwait(false);
                using var timer = new PeriodicTimer(period, Clock);
                while (await timer.WaitForNextTickAsync(token).ConfigureAwait(false))
                {
                    ClientConnection[] now = clients.Snapshot();
                    if (now.Length == 0)
                    {
                        break;
                    }
                    byte[] bytes = package();
                    foreach (ClientConnection client in now)
                    {
                        client.Send(bytes);
                    }
                }
            }
        }
        catch (OperationCanceledException)
        {
        }
    }

    /// <summary>Sends a robot message (a runtime exception or a text) to every primary and secondary client; made only when there is one.</summary>
    private void SendToStateClients(Func<byte[]> message)
    {
        ClientConnection[] now = _primaryClients.Snapshot();
        if (now.Length == 0)
        {
            return;
        }
        byte[] bytes = message();
        foreach (ClientConnection client in now)
        {
            client.Send(bytes);
        }
    }

    /// <summary>Milliseconds since the controller started, as robot messages stamp them.</summary>
    private ulong Timestamp => (ulong)Uptime.TotalMilliseconds;

    /// <summary>What the client interfaces report now: the twin's arm, program, I/O and the controller's modes.</summary>
    private VirtualUrClientState ClientState()
    {
        UrTwinController twin = Twin;
        Joints joints = twin.JointsNow();
        Pose tcp = twin.Arm.Model.Kinematics.Forward(joints) * twin.Arm.ToolCenter;
        Vector rv = RotationVectorOf(tcp.Rotation);
        Pose tool = twin.Arm.ToolCenter;
        Vector toolRv = RotationVectorOf(tool.Rotation);
        bool running = twin.State == UrProgramState.Running;
        return new VirtualUrClientState
        {
            Time = Uptime.TotalSeconds,
            Q = [.. joints.ToArray().Select(d => d * Math.PI / 180)],
            Qd = [.. twin.JointSpeedsNow().ToArray().Select(d => d * Math.PI / 180)],
            TcpSpeed = twin.TcpSpeedNow(),
            Tcp = [tcp.Position.X / 1000, tcp.Position.Y / 1000, tcp.Position.Z / 1000, rv.X, rv.Y, rv.Z],
            TcpOffset = [tool.Position.X / 1000, tool.Position.Y / 1000, tool.Position.Z / 1000, toolRv.X, toolRv.Y, toolRv.Z],
            RobotMode = RobotMode,
            SafetyMode = SafetyStatus,
            ProgramRunning = running,
            ProgramPaused = running && TwinHeld,
            RuntimeState = TwinRuntime(twin),
            DigitalInputs = DigitalBits(twin, UrIoBanks.StandardIn, UrIoBanks.ConfigurableIn, UrIoBanks.ToolIn),
            DigitalOutputs = DigitalBits(twin, UrIoBanks.StandardOut, UrIoBanks.ConfigurableOut, UrIoBanks.ToolOut),
            AnalogIn = [twin.Io.GetNumber(UrIoBanks.AnalogIn, 0), twin.Io.GetNumber(UrIoBanks.AnalogIn, 1)],
            AnalogOut = [twin.Io.GetNumber(UrIoBanks.AnalogOut, 0), twin.Io.GetNumber(UrIoBanks.AnalogOut, 1)],
            ToolAnalogIn = [twin.Io.GetNumber(UrIoBanks.ToolAnalogIn, 0), twin.Io.GetNumber(UrIoBanks.ToolAnalogIn, 1)],
            SpeedFraction = SpeedSlider,
        };
    }

    /// <summary>Digital bits as UR packs them: standard 0–7, configurable 8–15, tool 16–17.</summary>
    private static uint DigitalBits(UrTwinController twin, string standard, string configurable, string tool)
    {
        uint bits = 0;
        for (int i = 0; i < 8; i++)
        {
            bits |= (twin.Io.GetBit(standard, i) ? 1u : 0) << i;
            bits |= (twin.Io.GetBit(configurable, i) ? 1u : 0) << (8 + i);
        }
        for (int i = 0; i < 2; i++)
        {
            bits |= (twin.Io.GetBit(tool, i) ? 1u : 0) << (16 + i);
        }
        return bits;
    }

    /// <summary>One client of a client interface: its writes, one at a time, and dropped when it stops reading.</summary>
    private sealed class ClientConnection
    {
        private readonly Lock _write = new();
        private readonly TcpClient _client;
        private bool _gone;

        public ClientConnection(TcpClient client)
        {
            _client = client;
            client.SendTimeout = ClientSendTimeoutMs;
        }

        public void Send(byte[] bytes)
        {
            lock (_write)
            {
                if (_gone)
                {
                    return;
                }
                try
                {
                    _client.GetStream().Write(bytes);
                }
                catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or InvalidOperationException)
                {
                    _gone = true;
                    _client.Close(); // a client that stopped reading is dropped, as a controller does
                }
            }
        }
    }
}
