using System.Net.Sockets;
using Machina.Simulation.Twin;

namespace Machina.Simulation;

/// <summary>
/// The brand-neutral core of every virtual controller: the robot model, the driver connection acknowledgements go to, the
/// counts and logs, and the faults a test can inject. The arm and the program are the brand's twin (its interpreter runs the
/// driver); the twin's program thread tells the core what it received and, once its arm got there, acknowledges it through
/// the core on that same thread (<see cref="ReceiveOnCaller"/>, <see cref="CompleteReceivedOnCaller"/>): one path for every brand.
/// </summary>
/// <typeparam name="TState">The brand's snapshot of the robot.</typeparam>
public abstract partial class VirtualController<TState> : IAsyncDisposable where TState : VirtualRobotState
{
    /// <summary>How many pendant texts and errors are kept (oldest dropped).</summary>
    private protected const int MaxKeptTexts = 1000;

    private readonly VirtualControllerOptions _options;
    private readonly Lock _sendLock = new();
    /// <summary>
    /// The received requests' log: each entry its text, or what the brand writes it from (<see cref="RequestText"/>) until it is
    /// first read, when the text takes its place.
    /// </summary>
    private readonly VirtualControllerLog<object> _requestLog;
    private readonly VirtualControllerLog<string> _pendant = new(MaxKeptTexts);
    private readonly VirtualControllerLog<string> _errors = new(MaxKeptTexts);
    private readonly List<Task> _loops = [];
    private readonly TState _state;

    private CancellationTokenSource? _stopping;
    private TcpClient? _client;
    private Stream? _clientStream;

    /// <summary>Creates a stopped controller whose robot starts as <paramref name="initial"/> says, at the options' starting point.</summary>
    private protected VirtualController(VirtualControllerOptions options, Pose fallbackStart, Func<Vector, Rotation, Joints, TState> initial)
    {
        ArgumentNullException.ThrowIfNull(options);
        options.Validate();
        _options = options;
        _requestLog = new(options.RequestLogCapacity);
        _executedLog = new(options.RequestLogCapacity);
        Clock = options.TimeProvider;
        Model = options.Model;
        var (position, rotation, joints) = options.StartingPoint(fallbackStart);
        _state = initial(position, rotation, joints);
    }

    /// <summary>True between <c>StartAsync</c> and <see cref="StopAsync(CancellationToken)"/>.</summary>
    public bool IsRunning => _stopping is { IsCancellationRequested: false };

    /// <summary>The simulated arm, or null when joints and pose are kept apart.</summary>
    public RobotModel? Model { get; }

    /// <summary>The controller's clock.</summary>
    private protected TimeProvider Clock { get; }

    /// <summary>Guards the robot state and the logs; never held across an await.</summary>
    private protected Lock Gate { get; } = new();

    /// <summary>
    /// Set whenever something its inspection members show changes (a request received or executed, a pendant text, an error;
    /// its twin's signals once attached to it): a reader that shows them sleeps until then instead of looking on a timer.
    /// </summary>
    internal TwinChangeSignal Changes { get; } = new();

    /// <summary>Starts listening (and the brand's twin); a controller starts once.</summary>
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
    }

    /// <summary>Closes every connection, stops listening and waits for the background work to end. Never throws.</summary>
    public Task StopAsync() => StopAsync(CancellationToken.None);

    /// <summary>
    /// Closes every connection, stops listening and waits for the running program and the background work to end, holding no
    /// thread while they wind down. <paramref name="cancellationToken"/> ends the wait early (<see cref="OperationCanceledException"/>
    /// when a background loop had not ended yet): the controller is stopped all the same (no longer listening, its program told to
    /// stop) and what is left ends by itself. Throws nothing else.
    /// </summary>
    public async Task StopAsync(CancellationToken cancellationToken)
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
                await StopListeningAsync(cancellationToken).ConfigureAwait(false);
            }
            catch (Exception e) when (e is SocketException or ObjectDisposedException)
            {
                RecordError("stopping: " + e.Message);
            }
            finally
            {
                DropClient();
            }
        }
        Task[] loops;
        lock (Gate)
        {
            loops = [.. _loops];
        }
        try
        {
            await Task.WhenAll(loops).WaitAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            throw;
        }
        catch (Exception e)
        {
            // A loop that failed must not make stopping fail; what it met is kept for inspection.
            RecordError("a background loop failed: " + e.Message);
        }
    }

    /// <summary>Same as <see cref="StopAsync(CancellationToken)"/>.</summary>
    public async ValueTask DisposeAsync()
    {
        await StopAsync().ConfigureAwait(false);
        GC.SuppressFinalize(this);
    }

    /// <summary>Binds the brand's listeners and starts its loops with <see cref="Run"/>.</summary>
    private protected abstract Task ListenAsync(CancellationToken token);

    /// <summary>Stops the brand's listeners (the token given to <see cref="ListenAsync"/> is already cancelled).</summary>
    private protected abstract void StopListening();

    /// <summary>
    /// What <see cref="StopAsync(CancellationToken)"/> awaits to stop the brand's listeners and program. By default
    /// <see cref="StopListening"/> on a thread of its own, not the thread pool's (a brand's stop may join its program's threads for
    /// seconds); <paramref name="cancellationToken"/> ends the wait, not the stop. A brand whose program's end is a task overrides
    /// it to await that end.
    /// </summary>
    private protected virtual Task StopListeningAsync(CancellationToken cancellationToken) =>
        Task.Factory.StartNew(StopListening, CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default).WaitAsync(cancellationToken);

    /// <summary>Runs a background loop until the controller stops; <see cref="StopAsync(CancellationToken)"/> waits for it.</summary>
    private protected void Run(Func<CancellationToken, Task> loop)
    {
        var token = _stopping!.Token;
        lock (Gate)
        {
            _loops.Add(Task.Run(() => loop(token), CancellationToken.None));
        }
    }

    /// <summary>
    /// Runs a blocking loop on a thread of its own until the controller stops (<see cref="StopAsync(CancellationToken)"/> waits for it): a socket's
    /// reader that sleeps in the kernel's receive, where an asynchronous read wakes the thread pool, whose workers spin.
    /// </summary>
    private protected void RunOnThread(Action<CancellationToken> loop)
    {
        var token = _stopping!.Token;
        lock (Gate)
        {
            _loops.Add(Task.Factory.StartNew(() => loop(token), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default));
        }
    }

    /// <summary>
    /// Makes <paramref name="client"/> the driver connection, under the send lock (so the progress its greeting reports matches
    /// the acknowledgements sent). False when the fault plan refuses it (it is closed then). The controller writes to it through
    /// <paramref name="wire"/> when given (a twin's network stack that holds what its program sends), else its own stream.
    /// </summary>
    private protected bool AttachClient(TcpClient client, Stream? wire = null)
    {
        if (RefusesConnection())
        {
            client.Dispose();
            return false;
        }
        Stream stream = wire ?? client.GetStream();
        lock (_sendLock)
        {
            Interlocked.Increment(ref _connectionCount);
            lock (Gate)
            {
                _client = client;
                _clientStream = stream;
                _readerGeneration = _generation;
            }
        }
        return true;
    }

    /// <summary>Closes the driver connection (only if it is still <paramref name="only"/>, when given; otherwise that client alone).</summary>
    private protected void DropClient(TcpClient? only = null)
    {
        TcpClient? client;
        Stream? stream;
        lock (Gate)
        {
            client = _client;
            stream = _clientStream;
            if (only is not null && !ReferenceEquals(client, only))
            {
                only.Dispose();
                return;
            }
            _client = null;
            _clientStream = null;
        }
        FlushBeforeClose(stream);
        client?.Dispose();
    }

    /// <summary>What a twin's network stack still holds for the client goes out before it is closed (a no-op on a socket's own stream).</summary>
    private static void FlushBeforeClose(Stream? stream)
    {
        try
        {
            stream?.Flush();
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
        {
            // Already closed.
        }
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

    /// <summary>
    /// Writes to the current client, if any, on the caller's thread (a twin's program writes as a blocking socket write does); a
    /// positive <paramref name="executedId"/> is recorded as the last executed request first, under the same lock.
    /// </summary>
    private protected bool SendToClient(ReadOnlySpan<byte> bytes, int executedId = 0)
    {
        lock (_sendLock)
        {
            if (executedId > 0)
            {
                _lastExecutedId = executedId;
            }
            Stream? stream;
            lock (Gate)
            {
                stream = _clientStream;
            }
            if (stream is null)
            {
                return false;
            }
            try
            {
                stream.Write(bytes);
                return true;
            }
            catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
            {
                return false;
            }
        }
    }

    /// <summary>Fault injection from a test: <see cref="SendToClient"/> of <paramref name="bytes"/> unless cancelled first.</summary>
    private protected Task<bool> SendToClientAsync(byte[] bytes, CancellationToken token) =>
        token.IsCancellationRequested ? Task.FromCanceled<bool>(token) : Task.FromResult(SendToClient(bytes));

    /// <summary>
    /// Counts and logs a request received (and the most received but not yet executed): <paramref name="logEntry"/> is its text,
    /// or what <see cref="RequestText"/> writes it from when the log is read.
    /// </summary>
    private void CountReceived(object logEntry)
    {
        if (_options.RequestLogCapacity > 0)
        {
            lock (Gate)
            {
                _requestLog.Add(logEntry);
            }
        }
        int received = Interlocked.Increment(ref _requestsReceived);
        Changes.ChangedAfterFence();
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
            _pendant.Add(PrintableText.Of(text));
        }
        Changes.Changed();
    }

    /// <summary>Keeps an error (a malformed or refused request) and shows it on the pendant, made printable.</summary>
    private protected void RecordError(string error)
    {
        lock (Gate)
        {
            error = PrintableText.Of(error);
            _errors.Add(error);
            _pendant.Add("ERROR: " + error);
        }
        Changes.Changed();
    }
}
