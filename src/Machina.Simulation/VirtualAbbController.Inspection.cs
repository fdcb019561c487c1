namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    private int _connectionCount;
    private int _requestsReceived;
    private int _lastExecutedId;
    private int _lastReceivedId;
    private int _requestsExecuted;
    private int _acknowledgementsSent;
    private int _maxUnacknowledged;
    private int _monitorReportsSent;

    /// <summary>How many driver clients have connected (and received the handshake) so far.</summary>
    public int ConnectionCount => Volatile.Read(ref _connectionCount);

    /// <summary>How many well-formed requests have been read from the driver socket; a request is counted just before it enters the buffer, so it may still be on its way there.</summary>
    public int RequestsReceived => Volatile.Read(ref _requestsReceived);

    /// <summary>How many requests have been executed (acknowledged or, with no client, ack lost).</summary>
    public int RequestsExecuted => Volatile.Read(ref _requestsExecuted);

    /// <summary>How many acknowledgements actually reached a client.</summary>
    public int AcknowledgementsSent => Volatile.Read(ref _acknowledgementsSent);

    /// <summary>The largest number of requests received but not yet executed seen at any moment: how far the host streamed ahead.</summary>
    public int MaxUnacknowledged => Volatile.Read(ref _maxUnacknowledged);

    /// <summary>Requests waiting in the instruction buffer right now (at most <see cref="VirtualAbbControllerOptions.BufferCapacity"/>).</summary>
    public int BufferedRequestCount => _buffer.Reader.Count;

    /// <summary>How many state reports (<c>$24</c>) have been sent on the monitor port.</summary>
    public int MonitorReportsSent => Volatile.Read(ref _monitorReportsSent);

    /// <summary>The last received requests, as text ending in ';' (bounded by <see cref="VirtualAbbControllerOptions.RequestLogCapacity"/>).</summary>
    public IReadOnlyList<string> ReceivedRequests
    {
        get
        {
            lock (_gate)
            {
                return [.. _requestLog];
            }
        }
    }

    /// <summary>Texts the driver would have shown on the FlexPendant (TPWrite messages, errors), the last 1000.</summary>
    public IReadOnlyList<string> PendantMessages
    {
        get
        {
            lock (_gate)
            {
                return [.. _pendant];
            }
        }
    }

    /// <summary>Malformed requests received, with the reason (the real driver stops its program on these).</summary>
    public IReadOnlyList<string> Errors
    {
        get
        {
            lock (_gate)
            {
                return [.. _errors];
            }
        }
    }

    /// <summary>The robot state now: part-way through the current motion, or the last target reached.</summary>
    public VirtualAbbState State
    {
        get
        {
            lock (_gate)
            {
                return _motion is null ? _state : _motion.At(_time, _time.GetTimestamp());
            }
        }
    }

    /// <summary>Time between two monitor reports now (changed by instruction 103).</summary>
    public TimeSpan MonitorPeriod
    {
        get
        {
            lock (_gate)
            {
                return _monitorPeriod;
            }
        }
    }
}
