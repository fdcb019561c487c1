namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    private int _waitingOnCaller;

    /// <summary>
    /// For a twin whose program already did what it now acknowledges: counts the request, then does on the caller's thread (the
    /// program's) what the execution loop does for it: waits while the controller stops answering, logs it executed, and runs
    /// <see cref="AfterExecutedAsync"/> (the fault plan and the acknowledgement). No hand-off to another thread, so a streamed
    /// instruction costs no thread switch here. A controller uses this or <see cref="EnqueueAsync"/> for its acknowledgements,
    /// never both (their order would not be kept). A request a restart lost is not sent.
    /// </summary>
    private protected void AcknowledgeOnCaller(object request, int id, string logText, CancellationToken token)
    {
        if (!Receives(id, out int generation))
        {
            return; // read from a client a restart cut off: lost with the rest of the buffer
        }
        CountReceived(logText);
        // Waiting while the controller does not answer, it counts as buffered (as a queued request would).
        Interlocked.Increment(ref _waitingOnCaller);
        try
        {
            WhileStoppedAsync(token).GetAwaiter().GetResult();
        }
        finally
        {
            Interlocked.Decrement(ref _waitingOnCaller);
        }
        if (IsLost(generation))
        {
            // The robot already did it: only its acknowledgement is lost; it is in the execution log.
            LogExecuted(id);
            Interlocked.Increment(ref _requestsExecuted);
            return;
        }
        CompleteAsync(request, id, runs: true, token).GetAwaiter().GetResult();
    }
}

public abstract partial class VirtualController<TState>
{
    /// <summary>
    /// For a twin whose program reads a request now and acknowledges it later on the same thread (the RAPID driver: SocketReceive,
    /// then SocketSend): counts it received and buffered until <see cref="CompleteReceivedOnCaller"/>. A request that arrives from
    /// a client a restart cut off is counted too: it arrived on the program's socket, which the program still reads, so it may
    /// still run; <see cref="CompleteReceivedOnCaller"/> then logs it executed (if it ran) without acknowledging it. (It used to be
    /// dropped here while the program ran it: the host, told by the driver's progress that it ran, counted it executed and the
    /// controller's log missed it.)
    /// </summary>
    private protected void ReceiveOnCaller(int id, string logText, out int generation)
    {
        Receives(id, out generation);
        CountReceived(logText);
        Interlocked.Increment(ref _waitingOnCaller);
    }

    /// <summary>
    /// Completes on the caller's thread a request <see cref="ReceiveOnCaller"/> counted: waits while the controller stops
    /// answering, then logs it executed (unless <paramref name="runs"/> is false: the program skipped it) and runs
    /// <see cref="AfterExecutedAsync"/> (the fault plan and the acknowledgement). A request a restart lost is counted executed, unsent.
    /// </summary>
    private protected void CompleteReceivedOnCaller(object request, int id, int generation, bool runs, CancellationToken token)
    {
        try
        {
            WhileStoppedAsync(token).GetAwaiter().GetResult();
        }
        finally
        {
            Interlocked.Decrement(ref _waitingOnCaller);
        }
        if (IsLost(generation))
        {
            if (runs)
            {
                LogExecuted(id);
            }
            Interlocked.Increment(ref _requestsExecuted);
            return;
        }
        CompleteAsync(request, id, runs, token).GetAwaiter().GetResult();
    }
}
