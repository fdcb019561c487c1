using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    private readonly Queue<VirtualFault> _injected = new();
    private Random? _faultRandom;
    private int _faultAcknowledgements;
    private int _refusalsLeft;
    private int _requestsLost;

    /// <summary>Bumped by a restart that loses the buffer: requests read under an older generation are dropped, never executed.</summary>
    private int _generation;

    /// <summary>The generation of the client whose requests are being read (set when it is attached).</summary>
    private int _readerGeneration;

    /// <summary>The faults injected so far from the options' <c>Faults</c>, in order (the last 1000).</summary>
    public IReadOnlyList<VirtualFault> InjectedFaults
    {
        get
        {
            lock (Gate)
            {
                return [.. _injected];
            }
        }
    }

    /// <summary>How many received requests a restart lost before they were executed.</summary>
    public int RequestsLost => Volatile.Read(ref _requestsLost);

    /// <summary>Requests received and neither executed nor lost: what the driver holds (its ring, for KUKA).</summary>
    private protected int RequestsHeld => RequestsReceived - RequestsExecuted - RequestsLost;

    /// <summary>The brand's acknowledgement of <paramref name="id"/>, as its driver writes it.</summary>
    private protected abstract byte[] AcknowledgementBytes(int id);

    /// <summary>Bytes the brand's host cannot read as part of its protocol.</summary>
    private protected abstract byte[] GarbageBytes(Random random);

    /// <summary>
    /// A restart that loses the buffer begins (on the program's thread, at the acknowledgement, before the client is dropped): a brand whose driver is a
    /// program on the controller stops it here, so that no client can reach the program as it was before the restart.
    /// </summary>
    private protected virtual void RestartingLosingBuffer()
    {
    }

    /// <summary>
    /// A restart that loses the progress begins (on the program's thread or where a connection is refused, after the buffer was emptied and
    /// before the client is dropped): the brand's driver program starts again from its beginning with its progress at 0, and no
    /// client may reach the program as it was.
    /// </summary>
    private protected virtual void RestartingLosingProgress()
    {
    }

    /// <summary>Puts the robot in a protective stop, where the brand has one; false otherwise.</summary>
    private protected virtual bool InjectProtectiveStop() => false;

    /// <summary>An id no host sent (far ahead of <paramref name="id"/>), kept positive and within what the brand's wire carries.</summary>
    private protected virtual int UnknownId(int id) => id < int.MaxValue - 1_000_000 ? id + 1_000_000 : 1_000_000;

    /// <summary>Starts the fault plan of the options (called once, before the controller serves anyone).</summary>
    private void StartFaultPlan()
    {
        _faultRandom = new Random(_options.Faults.Seed);
        _refusalsLeft = _options.Faults.RefuseConnections;
    }

    /// <summary>True when the options say to refuse this connection attempt (it is then counted), or a restart is under way.</summary>
    private bool RefusesConnection()
    {
        if (RefusesUntilRestarted())
        {
            return true;
        }
        while (true)
        {
            int left = Volatile.Read(ref _refusalsLeft);
            if (left <= 0)
            {
                return false;
            }
            if (Interlocked.CompareExchange(ref _refusalsLeft, left - 1, left) == left)
            {
                Note(VirtualFault.None, "fault: connection refused");
                return true;
            }
        }
    }

    /// <summary>The fault that follows this acknowledgement (drawn on the program's thread, one acknowledgement at a time).</summary>
    private VirtualFault NextFault()
    {
        VirtualFaults plan = _options.Faults;
        if (plan.Chance == 0 && plan.After == 0)
        {
            return VirtualFault.None;
        }
        int n = ++_faultAcknowledgements;
        // Drawn for every acknowledgement, so that the sequence depends only on the seed and the count.
        bool strikes = plan.Chance > 0 && _faultRandom!.NextDouble() < plan.Chance;
        if (n != plan.After && !strikes)
        {
            return VirtualFault.None;
        }
        return plan.Kinds[plan.Kinds.Count == 1 ? 0 : _faultRandom!.Next(plan.Kinds.Count)];
    }

    /// <summary>
    /// Sends the acknowledgement of an executed request and counts it (or notes it lost when no client listens), with the
    /// fault the plan puts there, if any, on the program's thread: a delay holds the program as a slow network would.
    /// </summary>
    private protected void Acknowledge(ReadOnlySpan<byte> bytes, int id, CancellationToken token)
    {
        VirtualFault fault = NextFault();
        if (RunsTowardsRestart())
        {
            return; // the link is broken: the request ran, its acknowledgement is lost
        }
        if (fault != VirtualFault.None)
        {
            Note(fault, $"fault: {fault} after request {id.ToString(CultureInfo.InvariantCulture)}");
        }
        switch (fault)
        {
            case VirtualFault.Delay:
                TwinWait.Delay(_options.Faults.Delay, Clock, token);
                break;
            case VirtualFault.Garbage:
                SendToClient(GarbageBytes(_faultRandom!));
                break;
            case VirtualFault.UnknownAcknowledgement:
                SendToClient(AcknowledgementBytes(UnknownId(id)));
                break;
            case VirtualFault.RestartLosingProgress:
                BeginRestart();
                return;
            case VirtualFault.Truncate:
                // The request ran; only part of its acknowledgement leaves before the link breaks.
                int cut = bytes.Length > 1 ? 1 + _faultRandom!.Next(bytes.Length - 1) : 0;
                SendToClient(bytes[..cut], executedId: id);
                DropClient();
                return;
        }
        // Marked executed under the send lock: a handshake reports as executed exactly the requests whose
        // acknowledgement went to an earlier client (or was lost).
        if (SendToClient(bytes, executedId: id))
        {
            Interlocked.Increment(ref _acknowledgementsSent);
            CountTowardsClose();
        }
        else
        {
            Pendant("acknowledgement lost, client disconnected");
        }
        switch (fault)
        {
            case VirtualFault.Drop:
                DropClient();
                break;
            case VirtualFault.StopAnswering:
                StopAnswering();
                break;
            case VirtualFault.RestartKeepingBuffer:
                DropClient();
                TwinWait.Delay(_options.Faults.Delay, Clock, token);
                break;
            case VirtualFault.RestartLosingBuffer:
                LoseBuffer();
                break;
            case VirtualFault.ProtectiveStop:
                InjectProtectiveStop();
                break;
        }
    }

    /// <summary>
    /// A restart that loses what was received and not executed (called where the acknowledgement went out): the client is dropped, the
    /// buffer emptied, and the progress reports the last executed request as the last received one.
    /// </summary>
    private void LoseBuffer()
    {
        RestartingLosingBuffer();
        // Emptied before the client is dropped: a host that reconnects at once must not see its new requests drained.
        int lost = DiscardReceived();
        DropClient();
        Pendant($"restarted: {Counted.Of(lost, "request")} received and not executed {(lost == 1 ? "is" : "are")} lost");
    }

    /// <summary>
    /// A restart that loses the buffer and the progress (called where the acknowledgement went out): what was received and not
    /// executed is lost, the driver program starts afresh and reports 0 executed, 0 received, and the client is dropped. The
    /// execution log keeps what ran before: a request run again after the restart is there twice.
    /// </summary>
    private void LoseProgress()
    {
        int lost = DiscardReceived();
        ResetProgress();
        RestartingLosingProgress();
        DropClient();
        Pendant($"restarted: the driver program starts again with no progress (0 executed, 0 received); {lost.ToString(CultureInfo.InvariantCulture)} requests received and not executed are lost");
    }

    /// <summary>
    /// The driver dropped what it held (a stop on the controller): what was received and not executed is dropped, and so is
    /// what the current client still sends; the progress reports the last executed request as the last received one, and the
    /// next client is served as usual.
    /// </summary>
    private protected void DropBuffer(string why)
    {
        int dropped = DiscardReceived();
        Pendant($"{why}: {Counted.Of(dropped, "request")} received and not executed {(dropped == 1 ? "is" : "are")} dropped");
    }

    /// <summary>
    /// Forgets what was received and not executed: requests read under the current generation are lost from now on, what the
    /// brand's driver holds is dropped (<see cref="DiscardHeld"/>) and the progress reports the last executed request as the
    /// last received one. Returns how many requests were dropped.
    /// </summary>
    private int DiscardReceived()
    {
        lock (Gate)
        {
            _generation++;
            Volatile.Write(ref _lastReceivedId, Volatile.Read(ref _lastExecutedId));
        }
        int discarded = DiscardHeld();
        Interlocked.Add(ref _waitingOnCaller, -discarded);
        Interlocked.Add(ref _requestsLost, discarded);
        return discarded;
    }

    /// <summary>
    /// Checks that a request read from the current client may be held and records it as the last received (false
    /// when a restart since that client attached lost it).
    /// </summary>
    private bool Receives(int id, out int generation)
    {
        lock (Gate)
        {
            generation = _readerGeneration;
            if (generation != _generation)
            {
                return false;
            }
            if (id > 0)
            {
                Volatile.Write(ref _lastReceivedId, id);
            }
            return true;
        }
    }

    /// <summary>True (and the request counted as lost) when a restart lost <paramref name="generation"/>'s requests.</summary>
    private bool IsLost(int generation)
    {
        if (generation == Volatile.Read(ref _generation))
        {
            return false;
        }
        Interlocked.Increment(ref _requestsLost);
        return true;
    }

    private void Note(VirtualFault fault, string text)
    {
        lock (Gate)
        {
            if (fault != VirtualFault.None)
            {
                _injected.Enqueue(fault);
                while (_injected.Count > MaxKeptTexts)
                {
                    _injected.Dequeue();
                }
            }
        }
        Pendant(text);
    }
}
