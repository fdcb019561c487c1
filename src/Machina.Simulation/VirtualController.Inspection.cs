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
    private readonly VirtualControllerLog<int> _executedLog;

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
    public IReadOnlyList<string> ReceivedRequests
    {
        get
        {
            lock (Gate)
            {
                var texts = new string[_requestLog.Count];
                for (int k = 0; k < texts.Length; k++)
                {
                    texts[k] = RequestTextAt(k);
                }
                return texts;
            }
        }
    }

    /// <summary>
    /// The text of the received requests' log's kept entry <paramref name="k"/>: the entry itself once it is text, else what the
    /// brand writes from the entry it logged (<see cref="RequestText"/>), stored back in its place so that it is written once.
    /// Called under the gate.
    /// </summary>
    private string RequestTextAt(int k)
    {
        ref object entry = ref _requestLog.At(k);
        if (entry is not string text)
        {
            text = RequestText(entry);
            entry = text;
        }
        return text;
    }

    /// <summary>
    /// The text of an entry of the received requests' log that is not text yet: what the brand writes from the entry it logged
    /// (<see cref="ReceiveOnCaller"/>). Called under the gate, once per entry (the log keeps the text in the entry's place).
    /// </summary>
    private protected virtual string RequestText(object entry) => entry.ToString() ?? "";

    /// <summary>Texts the driver would have shown on the teach pendant (messages, errors), the last 1000.</summary>
    public IReadOnlyList<string> PendantMessages => Copy(_pendant);

    /// <summary>Malformed or refused requests, with the reason (the last 1000); the controller keeps serving after each.</summary>
    public IReadOnlyList<string> Errors => Copy(_errors);

    /// <summary>
    /// Adds to <paramref name="into"/> the requests received (as <see cref="ReceivedRequests"/> has them) after the first
    /// <paramref name="seen"/> ever logged, those still kept, oldest first; returns how many were ever logged: the
    /// <paramref name="seen"/> of the next read. A reader who polls copies only what is new, and nothing when nothing is (the
    /// count is read first, without the lock).
    /// </summary>
    public long ReceivedRequestsSince(long seen, ICollection<string> into)
    {
        ArgumentNullException.ThrowIfNull(into);
        if (_requestLog.Total == seen)
        {
            return seen;
        }
        lock (Gate)
        {
            for (int k = _requestLog.FirstSince(seen); k < _requestLog.Count; k++)
            {
                into.Add(RequestTextAt(k));
            }
            return _requestLog.Total;
        }
    }

    /// <summary>As <see cref="ReceivedRequestsSince"/>, for <see cref="ExecutedIds"/>.</summary>
    public long ExecutedIdsSince(long seen, ICollection<int> into) => Since(_executedLog, seen, into);

    /// <summary>As <see cref="ReceivedRequestsSince"/>, for <see cref="PendantMessages"/>.</summary>
    public long PendantMessagesSince(long seen, ICollection<string> into) => Since(_pendant, seen, into);

    /// <summary>As <see cref="ReceivedRequestsSince"/>, for <see cref="Errors"/>.</summary>
    public long ErrorsSince(long seen, ICollection<string> into) => Since(_errors, seen, into);

    /// <summary>A copy of one of the controller's logs, taken under its lock.</summary>
    private T[] Copy<T>(VirtualControllerLog<T> log)
    {
        lock (Gate)
        {
            return log.ToArray();
        }
    }

    /// <summary>What <paramref name="log"/> took after the first <paramref name="seen"/> entries; the lock only when there is some.</summary>
    private long Since<T>(VirtualControllerLog<T> log, long seen, ICollection<T> into)
    {
        ArgumentNullException.ThrowIfNull(into);
        long total = log.Total;
        if (total == seen)
        {
            return total;
        }
        lock (Gate)
        {
            return log.CopySince(seen, into);
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
                _executedLog.Add(id);
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
