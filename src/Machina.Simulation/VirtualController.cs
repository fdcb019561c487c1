using System.Net.Sockets;
using System.Threading.Channels;

namespace Machina.Simulation;

/// <summary>
/// The brand-neutral core of every virtual controller: the simulated arm (its state, robot model and motion timing), the
/// instruction buffer executed in order, the driver connection acknowledgements go to, the logs, and the faults a test can
/// inject. A brand adds only its protocol: how it listens, parses requests, plans each instruction and acknowledges it.
/// </summary>
/// <typeparam name="TState">The brand's snapshot of the robot.</typeparam>
public abstract partial class VirtualController<TState> : IAsyncDisposable where TState : VirtualRobotState
{
    /// <summary>How many pendant texts and errors are kept (oldest dropped).</summary>
    private protected const int MaxKeptTexts = 1000;

    private readonly VirtualControllerOptions _options;
    private readonly SemaphoreSlim _sendLock = new(1, 1);
    private readonly Channel<Queued> _buffer;
    private readonly Queue<string> _requestLog = new();
    private readonly Queue<string> _pendant = new();
    private readonly Queue<string> _errors = new();
    private readonly List<Task> _loops = [];

    private CancellationTokenSource? _stopping;
    private TcpClient? _client;
    private NetworkStream? _clientStream;
    private TState _state;
    private VirtualMotion? _motion;

    /// <summary>Creates a stopped controller whose robot starts as <paramref name="initial"/> says, at the options' starting point.</summary>
    private protected VirtualController(VirtualControllerOptions options, Pose fallbackStart, Func<Vector, Rotation, Joints, TState> initial)
    {
        ArgumentNullException.ThrowIfNull(options);
        options.Validate();
        _options = options;
        Clock = options.TimeProvider;
        Model = options.Model;
        _buffer = Channel.CreateBounded<Queued>(new BoundedChannelOptions(options.BufferCapacity)
        {
            SingleReader = true,
            SingleWriter = true,
            FullMode = BoundedChannelFullMode.Wait,
        });
        var (position, rotation, joints) = options.StartingPoint(fallbackStart);
        _state = initial(position, rotation, joints);
    }

    /// <summary>True between <c>StartAsync</c> and <see cref="StopAsync"/>.</summary>
    public bool IsRunning => _stopping is { IsCancellationRequested: false };

    /// <summary>The simulated arm, or null when joints and pose are kept apart.</summary>
    public RobotModel? Model { get; }

    /// <summary>The controller's clock.</summary>
    private protected TimeProvider Clock { get; }

    /// <summary>Guards the robot state and the logs; never held across an await.</summary>
    private protected Lock Gate { get; } = new();

    /// <summary>Starts listening and the execution loop; a controller starts once.</summary>
    public async Task StartAsync(CancellationToken cancellationToken = default)
    {
        cancellationToken.ThrowIfCancellationRequested();
        if (_stopping is not null)
        {
            throw new InvalidOperationException("This virtual controller was already started; create a new one.");
        }
        _stopping = new CancellationTokenSource();
        StartFaultPlan();
        await ListenAsync(_stopping.Token).ConfigureAwait(false);
        Run(ExecuteRequestsAsync);
    }

    /// <summary>Closes every connection, stops listening and waits for the background work to end. Never throws.</summary>
    public async Task StopAsync()
    {
        if (_stopping is null)
        {
            return;
        }
        if (!_stopping.IsCancellationRequested)
        {
            await _stopping.CancelAsync().ConfigureAwait(false);
            try
            {
                StopListening();
            }
            catch (Exception e) when (e is SocketException or ObjectDisposedException)
            {
                RecordError("stopping: " + e.Message);
            }
            DropClient();
        }
        Task[] loops;
        lock (Gate)
        {
            loops = [.. _loops];
        }
        try
        {
            await Task.WhenAll(loops).ConfigureAwait(false);
        }
        catch (Exception e)
        {
            // A loop that failed must not make stopping fail; what it met is kept for inspection.
            RecordError("a background loop failed: " + e.Message);
        }
    }

    /// <summary>Same as <see cref="StopAsync"/>.</summary>
    public async ValueTask DisposeAsync()
    {
        await StopAsync().ConfigureAwait(false);
        GC.SuppressFinalize(this);
    }

    /// <summary>Binds the brand's listeners and starts its loops with <see cref="Run"/>.</summary>
    private protected abstract Task ListenAsync(CancellationToken token);

    /// <summary>Stops the brand's listeners (the token given to <see cref="ListenAsync"/> is already cancelled).</summary>
    private protected abstract void StopListening();

    /// <summary>Runs a background loop until the controller stops; <see cref="StopAsync"/> waits for it.</summary>
    private protected void Run(Func<CancellationToken, Task> loop)
    {
        var token = _stopping!.Token;
        lock (Gate)
        {
            _loops.Add(Task.Run(() => loop(token), CancellationToken.None));
        }
    }

    /// <summary>
    /// Makes <paramref name="client"/> the driver connection after <paramref name="greet"/> wrote the brand's handshake,
    /// under the send lock (so the progress it reports matches the acknowledgements sent). False when the client left.
    /// </summary>
    private protected async Task<bool> AttachClientAsync(TcpClient client, Func<NetworkStream, CancellationToken, Task> greet, CancellationToken token)
    {
        if (RefusesConnection())
        {
            client.Dispose();
            return false;
        }
        var stream = client.GetStream();
        try
        {
            await _sendLock.WaitAsync(token).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            client.Dispose();
            return false;
        }
        Interlocked.Increment(ref _connectionCount);
        try
        {
            await greet(stream, token).ConfigureAwait(false);
            lock (Gate)
            {
                _client = client;
                _clientStream = stream;
                _readerGeneration = _generation;
            }
            return true;
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            client.Dispose();
            return false;
        }
        finally
        {
            _sendLock.Release();
        }
    }

    /// <summary>Closes the driver connection (only if it is still <paramref name="only"/>, when given; otherwise that client alone).</summary>
    private protected void DropClient(TcpClient? only = null)
    {
        TcpClient? client;
        lock (Gate)
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

    /// <summary>True while a driver connection is open.</summary>
    private protected bool HasClient
    {
        get
        {
            lock (Gate)
            {
                return _client is not null;
            }
        }
    }

    /// <summary>Writes to the current client, if any; a positive <paramref name="executedId"/> is recorded as the last executed request first, under the same lock.</summary>
    private protected async Task<bool> SendToClientAsync(ReadOnlyMemory<byte> bytes, CancellationToken token, int executedId = 0)
    {
        await _sendLock.WaitAsync(token).ConfigureAwait(false);
        try
        {
            if (executedId > 0)
            {
                _lastExecutedId = executedId;
            }
            NetworkStream? stream;
            lock (Gate)
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

    /// <summary>Puts a parsed request into the instruction buffer, waiting while it is full; counts and logs it.</summary>
    private protected async ValueTask EnqueueAsync(object request, int id, string logText, CancellationToken token)
    {
        if (!Receives(id, out int generation))
        {
            return; // read from a client a restart cut off: lost with the rest of the buffer
        }
        CountReceived(logText);
        await _buffer.Writer.WriteAsync(new Queued(request, id, generation), token).ConfigureAwait(false);
    }

    /// <summary>Counts and logs a request received (and the most received but not yet executed).</summary>
    private void CountReceived(string logText)
    {
        if (_options.RequestLogCapacity > 0)
        {
            lock (Gate)
            {
                Keep(_requestLog, logText, _options.RequestLogCapacity);
            }
        }
        int received = Interlocked.Increment(ref _requestsReceived);
        int unacknowledged = received - Volatile.Read(ref _requestsExecuted);
        int seen;
        while (unacknowledged > (seen = Volatile.Read(ref _maxUnacknowledged))
            && Interlocked.CompareExchange(ref _maxUnacknowledged, unacknowledged, seen) != seen)
        {
        }
    }

    /// <summary>Keeps a text the driver would show on the teach pendant (made printable: it can carry bytes from the wire).</summary>
    private protected void Pendant(string text)
    {
        lock (Gate)
        {
            Keep(_pendant, PrintableText.Of(text), MaxKeptTexts);
        }
    }

    /// <summary>Keeps an error (a malformed or refused request) and shows it on the pendant, made printable.</summary>
    private protected void RecordError(string error)
    {
        lock (Gate)
        {
            error = PrintableText.Of(error);
            Keep(_errors, error, MaxKeptTexts);
            Keep(_pendant, "ERROR: " + error, MaxKeptTexts);
        }
    }

    private static void Keep<T>(Queue<T> queue, T text, int capacity)
    {
        queue.Enqueue(text);
        while (queue.Count > capacity)
        {
            queue.Dequeue();
        }
    }

    /// <summary>A request in the buffer with the id it is acknowledged by.</summary>
    private readonly record struct Queued(object Request, int Id, int Generation);
}
