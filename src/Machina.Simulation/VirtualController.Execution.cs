using System.Globalization;

namespace Machina.Simulation;

/// <summary>
/// The one way a twin acknowledges. Its arm runs the driver's instructions on the program's own thread, so the core has no
/// queue and no execution loop of its own: the program tells the core what it received (<see cref="ReceiveOnCaller"/>), and
/// when its arm got there and it writes the acknowledgement, the core settles that request on the same thread
/// (<see cref="CompleteReceivedOnCaller"/>: the pause, the execution log, the fault plan, the acknowledgement), or takes the
/// driver's failure report instead (<see cref="RefuseOnCaller"/>). No hand-off to another thread per action, and nothing
/// waits on a task except a real wait (a pause, a delay the fault plan puts there).
/// </summary>
public abstract partial class VirtualController<TState>
{
    /// <summary>
    /// The generation a brand gives a request whose losses in a restart it settles itself (<see cref="DiscardHeld"/> takes
    /// them): its completion is not judged by generation again.
    /// </summary>
    private protected const int SettledByBrand = -1;

    /// <summary>Requests received and not yet settled: what the brand's driver holds.</summary>
    private int _waitingOnCaller;

    /// <summary>Acknowledges an executed request (and whatever else the brand's driver sends then), on the program's thread.</summary>
    private protected abstract void AfterExecuted(object request, int id, CancellationToken token);

    /// <summary>
    /// A restart lost what was received and not executed: the brand drops the requests its driver holds (those it may still
    /// run are settled by <see cref="RanOutsideBuffer"/> when it does) and returns how many; they count as lost. Called once the
    /// generation moved on, so no request of the old one is received after it.
    /// </summary>
    private protected virtual int DiscardHeld() => 0;

    /// <summary>
    /// Counts a request the twin's program received: it is held (<see cref="BufferedRequestCount"/>) until settled. A request
    /// from a client a restart cut off is counted only with <paramref name="keepsCut"/> (the RAPID driver still reads its
    /// socket, so it may still run; <see cref="CompleteReceivedOnCaller"/> then logs it without acknowledging it). False when
    /// it was not counted.
    /// </summary>
    /// <remarks>
    /// <paramref name="logEntry"/> is the request's text for the log, or what the brand's <see cref="RequestText"/> writes the text
    /// from when someone first reads the log (a streamed request's text is then written only if it is read, and once: the log keeps it).
    /// </remarks>
    private protected bool ReceiveOnCaller(int id, object logEntry, out int generation, bool keepsCut = false)
    {
        if (!Receives(id, out generation) && !keepsCut)
        {
            return false; // read from a client a restart cut off: lost with the rest of what the driver held
        }
        CountReceived(logEntry);
        Interlocked.Increment(ref _waitingOnCaller);
        return true;
    }

    /// <summary>
    /// Settles, on the caller's thread, a request <see cref="ReceiveOnCaller"/> counted and the twin's arm ran: waits while the
    /// controller stops answering, logs it executed (unless <paramref name="runs"/> is false: the program skipped it), counts
    /// it and runs <see cref="AfterExecuted"/> (the fault plan and the acknowledgement). A request a restart lost is counted
    /// executed (and lost), unsent.
    /// </summary>
    private protected void CompleteReceivedOnCaller(object request, int id, int generation, bool runs, CancellationToken token)
    {
        try
        {
            WhileStopped(token);
        }
        finally
        {
            Interlocked.Decrement(ref _waitingOnCaller);
        }
        if (runs)
        {
            LogExecuted(id);
        }
        Interlocked.Increment(ref _requestsExecuted);
        Changes.ChangedAfterFence();
        if (generation != SettledByBrand && IsLost(generation))
        {
            return;
        }
        // Before the acknowledgement goes out: whoever sees it also sees the pause it may start.
        CountTowardsPause();
        try
        {
            AfterExecuted(request, id, token);
        }
        catch (Exception e) when (e is not OperationCanceledException)
        {
            RecordError($"answering request {id.ToString(CultureInfo.InvariantCulture)} failed: {e.Message}");
        }
    }

    /// <summary>
    /// For a twin whose program received a request just now and already ran it (the UR driver: its acknowledgement is the first
    /// the controller hears of it): <see cref="ReceiveOnCaller"/> then <see cref="CompleteReceivedOnCaller"/>. Nothing is sent
    /// for a request a restart lost.
    /// </summary>
    private protected void AcknowledgeOnCaller(object request, int id, object logEntry, CancellationToken token)
    {
        if (ReceiveOnCaller(id, logEntry, out int generation))
        {
            CompleteReceivedOnCaller(request, id, generation, runs: true, token);
        }
    }

    /// <summary>
    /// Settles a request the twin's driver refused instead of running it (it reported the failure with the controller's
    /// words): kept as an error, counted executed but not logged (nothing of it ran), nothing acknowledged.
    /// </summary>
    private protected void RefuseOnCaller(string reason)
    {
        RecordError("refused: " + reason);
        Interlocked.Decrement(ref _waitingOnCaller);
        Interlocked.Increment(ref _requestsExecuted);
        Changes.ChangedAfterFence();
        CountTowardsPause();
    }

    /// <summary>A held request a restart lost before the driver ran it (and <see cref="DiscardHeld"/> did not count): counted lost.</summary>
    private protected void LostOnCaller()
    {
        Interlocked.Decrement(ref _waitingOnCaller);
        Interlocked.Increment(ref _requestsLost);
    }
}
