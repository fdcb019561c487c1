namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    private int _connectionCount;
    private int _requestsReceived;
    private int _lastExecutedId;
    private int _lastReceivedId;
    private int _requestsExecuted;
    private int _acknowledgementsSent;
    private int _maxUnacknowledged;
    private readonly Queue<int> _executedLog = new();

    /// <summary>How many driver clients have connected (and received the handshake) so far.</summary>
    public int ConnectionCount => Volatile.Read(ref _connectionCount);

    /// <summary>How many well-formed requests have been read from the driver connection; a request is counted just before it enters the buffer, so it may still be on its way there.</summary>
    public int RequestsReceived => Volatile.Read(ref _requestsReceived);

    /// <summary>How many requests have been executed or refused (acknowledged or, with no client, ack lost).</summary>
    public int RequestsExecuted => Volatile.Read(ref _requestsExecuted);

    /// <summary>
    /// The wire ids of the requests executed (or refused), in the order the robot ran them: the controller's execution log,
    /// bounded like <see cref="ReceivedRequests"/> by the options' <c>RequestLogCapacity</c>. A request run twice is there twice.
    /// </summary>
    public IReadOnlyList<int> ExecutedIds => Copy(_executedLog);

    /// <summary>How many acknowledgements actually reached a client.</summary>
    public int AcknowledgementsSent => Volatile.Read(ref _acknowledgementsSent);

    /// <summary>The largest number of requests received but not yet executed seen at any moment: how far the host streamed ahead.</summary>
    public int MaxUnacknowledged => Volatile.Read(ref _maxUnacknowledged);

    /// <summary>Requests received and not yet executed, refused or lost right now: what the driver holds (the KUKA driver's ring, the ABB driver's socket).</summary>
    public int BufferedRequestCount => Volatile.Read(ref _waitingOnCaller);

    /// <summary>The last received requests, as text (bounded by the options' <c>RequestLogCapacity</c>).</summary>
    public IReadOnlyList<string> ReceivedRequests => Copy(_requestLog);

    /// <summary>Texts the driver would have shown on the teach pendant (messages, errors), the last 1000.</summary>
    public IReadOnlyList<string> PendantMessages => Copy(_pendant);

    /// <summary>Malformed or refused requests, with the reason (the last 1000); the controller keeps serving after each.</summary>
    public IReadOnlyList<string> Errors => Copy(_errors);

    /// <summary>A copy of one of the controller's logs, taken under its lock.</summary>
    private T[] Copy<T>(Queue<T> log)
    {
        lock (Gate)
        {
            return [.. log];
        }
    }

    /// <summary>The robot state now: where the twin's arm is (part-way through a motion too), with its outputs.</summary>
    public TState State => Observe(_state);

    /// <summary>The state as the brand's arm has it now, from the one the controller kept (a twin reads its own arm and outputs).</summary>
    private protected virtual TState Observe(TState kept) => kept;

    private void LogExecuted(int id)
    {
        if (id > 0 && _options.RequestLogCapacity > 0)
        {
            lock (Gate)
            {
                Keep(_executedLog, id, _options.RequestLogCapacity);
            }
        }
    }

    /// <summary>The wire id of the last request executed (0 when none); read it while greeting a client, under the send lock.</summary>
    private protected int LastExecutedId => Volatile.Read(ref _lastExecutedId);

    /// <summary>The wire id of the last request received (0 when none).</summary>
    private protected int LastReceivedId => Volatile.Read(ref _lastReceivedId);

    /// <summary>Forgets the progress, for a new driver program that starts counting again.</summary>
    private protected void ResetProgress()
    {
        Volatile.Write(ref _lastExecutedId, 0);
        Volatile.Write(ref _lastReceivedId, 0);
    }
}
