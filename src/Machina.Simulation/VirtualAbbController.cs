using System.Net;
using System.Net.Sockets;
using System.Text;
using System.Threading.Channels;

namespace Machina.Simulation;

/// <summary>
/// A stand-in for an ABB controller running Machina's RAPID driver and monitor, listening on 127.0.0.1.
/// It answers the handshake, executes requests in order with a simple motion model, acknowledges each one
/// after execution, and streams state reports on the monitor port (driver port + 1). Made for tests and demos.
/// </summary>
public sealed partial class VirtualAbbController : IAsyncDisposable
{
    private const int MaxPortAttempts = 50;
    private const int MaxKeptTexts = 1000;

    private readonly VirtualAbbControllerOptions _options;
    private readonly TimeProvider _time;
    private readonly Lock _gate = new();
    private readonly SemaphoreSlim _sendLock = new(1, 1);
    private readonly Channel<AbbRequest> _buffer;
    private readonly Queue<string> _requestLog = new();
    private readonly Queue<string> _pendant = new();
    private readonly List<string> _errors = [];
    private readonly List<Task> _loops = [];

    private CancellationTokenSource? _stopping;
    private TcpListener? _driverListener;
    private TcpListener? _monitorListener;
    private TcpClient? _client;
    private NetworkStream? _clientStream;
    private VirtualAbbState _state;
    private VirtualMotion? _motion;
    private TimeSpan _monitorPeriod;

    /// <summary>Creates a stopped controller; call <see cref="StartAsync"/> to listen.</summary>
    public VirtualAbbController(VirtualAbbControllerOptions? options = null)
    {
        _options = options ?? new VirtualAbbControllerOptions();
        _options.Validate();
        _time = _options.TimeProvider;
        _monitorPeriod = _options.MonitorPeriod;
        _buffer = Channel.CreateBounded<AbbRequest>(new BoundedChannelOptions(_options.BufferCapacity)
        {
            SingleReader = true,
            SingleWriter = true,
            FullMode = BoundedChannelFullMode.Wait,
        });
        _state = new VirtualAbbState
        {
            Position = _options.InitialPosition,
            Rotation = _options.InitialRotation,
            Joints = _options.InitialJoints,
            ExternalAxesCartesian = _options.InitialExternalAxes,
            ExternalAxesJoints = _options.InitialExternalAxes,
        };
    }

    /// <summary>TCP port of the driver (requests and acknowledgements); 0 until started.</summary>
    public int Port { get; private set; }

    /// <summary>TCP port of the monitor (state reports), always <see cref="Port"/> + 1; 0 until started.</summary>
    public int MonitorPort { get; private set; }

    /// <summary>True between <see cref="StartAsync"/> and <see cref="StopAsync"/>.</summary>
    public bool IsRunning => _stopping is { IsCancellationRequested: false };

    /// <summary>Starts listening on 127.0.0.1 on an OS-chosen port P (driver) and P + 1 (monitor).</summary>
    public Task StartAsync(CancellationToken cancellationToken = default)
    {
        cancellationToken.ThrowIfCancellationRequested();
        if (_stopping is not null)
        {
            throw new InvalidOperationException("This virtual controller was already started; create a new one.");
        }
        (_driverListener, _monitorListener) = BindPortPair();
        Port = ((IPEndPoint)_driverListener.LocalEndpoint).Port;
        MonitorPort = Port + 1;
        _stopping = new CancellationTokenSource();
        var token = _stopping.Token;
        _loops.Add(Task.Run(() => AcceptDriverClientsAsync(token), CancellationToken.None));
        _loops.Add(Task.Run(() => AcceptMonitorClientsAsync(token), CancellationToken.None));
        _loops.Add(Task.Run(() => ExecuteRequestsAsync(token), CancellationToken.None));
        return Task.CompletedTask;
    }

    /// <summary>Closes every connection, stops listening and waits for the background work to end.</summary>
    public async Task StopAsync()
    {
        if (_stopping is null || _stopping.IsCancellationRequested)
        {
            await Task.WhenAll(_loops).ConfigureAwait(false);
            return;
        }
        await _stopping.CancelAsync().ConfigureAwait(false);
        _driverListener?.Stop();
        _monitorListener?.Stop();
        DropClient();
        await Task.WhenAll(_loops).ConfigureAwait(false);
        _stopping.Dispose();
    }

    /// <summary>Same as <see cref="StopAsync"/>.</summary>
    public async ValueTask DisposeAsync()
    {
        await StopAsync().ConfigureAwait(false);
        _sendLock.Dispose();
    }

    private static (TcpListener Driver, TcpListener Monitor) BindPortPair()
    {
        for (int attempt = 0; ; attempt++)
        {
            var driver = new TcpListener(IPAddress.Loopback, 0);
            driver.Start();
            int port = ((IPEndPoint)driver.LocalEndpoint).Port;
            if (port < IPEndPoint.MaxPort)
            {
                var monitor = new TcpListener(IPAddress.Loopback, port + 1);
                try
                {
                    monitor.Start();
                    return (driver, monitor);
                }
                catch (SocketException) when (attempt < MaxPortAttempts)
                {
                    // P + 1 is taken: try another pair.
                }
            }
            driver.Stop();
            if (attempt >= MaxPortAttempts)
            {
                throw new InvalidOperationException("Could not find two free consecutive ports on 127.0.0.1.");
            }
        }
    }

    private async Task AcceptDriverClientsAsync(CancellationToken token)
    {
        while (!token.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await _driverListener!.AcceptTcpClientAsync(token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException or InvalidOperationException)
            {
                return;
            }
            client.NoDelay = true;
            await ServeDriverClientAsync(client, token).ConfigureAwait(false);
        }
    }

    private async Task ServeDriverClientAsync(TcpClient client, CancellationToken token)
    {
        var stream = client.GetStream();
        try
        {
            await _sendLock.WaitAsync(token).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            client.Dispose();
            return;
        }
        Interlocked.Increment(ref _connectionCount);
        try
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
                handshake.Add(AbbMessageFormat.Progress(_lastExecutedId, Volatile.Read(ref _lastReceivedId)));
            }
            foreach (string message in handshake)
            {
                await stream.WriteAsync(Encoding.ASCII.GetBytes(message), token).ConfigureAwait(false);
            }
            lock (_gate)
            {
                _client = client;
                _clientStream = stream;
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            client.Dispose();
            return;
        }
        finally
        {
            _sendLock.Release();
        }
        await ReadRequestsAsync(stream, token).ConfigureAwait(false);
        DropClient(client);
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
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException or ChannelClosedException)
        {
            // Client gone or controller stopping: like the driver, keep executing what is buffered.
        }
    }

    /// <summary>Parses one statement into the buffer; false when it is malformed (the strict driver would stop).</summary>
    private async Task<bool> AcceptStatementAsync(string text, CancellationToken token)
    {
        lock (_gate)
        {
            if (_options.RequestLogCapacity > 0)
            {
                Keep(_requestLog, text.Trim() + ";", _options.RequestLogCapacity);
            }
        }
        if (!AbbRequestParser.TryParse(text, out var request, out string? error))
        {
            lock (_gate)
            {
                _errors.Add(error!);
                Keep(_pendant, "ERROR: " + error, MaxKeptTexts);
            }
            return false;
        }
        int received = Interlocked.Increment(ref _requestsReceived);
        int unacknowledged = received - Volatile.Read(ref _requestsExecuted);
        int seen;
        while (unacknowledged > (seen = Volatile.Read(ref _maxUnacknowledged))
            && Interlocked.CompareExchange(ref _maxUnacknowledged, unacknowledged, seen) != seen)
        {
        }
        if (request.Id > 0)
        {
            Volatile.Write(ref _lastReceivedId, request.Id);
        }
        await _buffer.Writer.WriteAsync(request, token).ConfigureAwait(false);
        return true;
    }

    private void DropClient(TcpClient? only = null)
    {
        TcpClient? client;
        lock (_gate)
        {
            client = _client;
            if (only is not null && !ReferenceEquals(client, only))
            {
                only.Dispose();
                return;
            }
            _client = null;
            _clientStream = null;
        }
        client?.Dispose();
    }

    /// <summary>Writes to the current client, if any; a positive <paramref name="executedId"/> is recorded as the last executed request first, under the same lock.</summary>
    private async Task<bool> SendToClientAsync(string text, CancellationToken token, int executedId = 0)
    {
        byte[] bytes = Encoding.ASCII.GetBytes(text);
        await _sendLock.WaitAsync(token).ConfigureAwait(false);
        try
        {
            if (executedId > 0)
            {
                _lastExecutedId = executedId;
            }
            NetworkStream? stream;
            lock (_gate)
            {
                stream = _clientStream;
            }
            if (stream is null)
            {
                return false;
            }
            await stream.WriteAsync(bytes, token).ConfigureAwait(false);
            return true;
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
        {
            return false;
        }
        finally
        {
            _sendLock.Release();
        }
    }

    private static void Keep(Queue<string> queue, string text, int capacity)
    {
        queue.Enqueue(text);
        while (queue.Count > capacity)
        {
            queue.Dequeue();
        }
    }
}
