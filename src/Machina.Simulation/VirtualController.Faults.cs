using Machina.Simulation.Twin;

namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    private readonly Lock _pauseGate = new();
    private TaskCompletionSource? _paused;
    private int _closeAfterAcknowledgements = -1;
    private int _answerBudget = -1;

    /// <summary>Fault injection: close the driver connection right after <paramref name="acknowledgements"/> more acknowledgements (0 = now).</summary>
    public void CloseConnectionAfter(int acknowledgements)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(acknowledgements);
        if (acknowledgements == 0)
        {
            DropClient();
            return;
        }
        Volatile.Write(ref _closeAfterAcknowledgements, acknowledgements);
    }

    /// <summary>Fault injection: stop executing and acknowledging (requests are still read into the buffer) until <see cref="ResumeAnswering()"/>.</summary>
    public void StopAnswering()
    {
        lock (_pauseGate)
        {
            _paused ??= new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        }
    }

    /// <summary>Ends <see cref="StopAnswering"/>: buffered requests are executed and acknowledged again.</summary>
    public void ResumeAnswering()
    {
        TaskCompletionSource? paused;
        lock (_pauseGate)
        {
            paused = _paused;
            _paused = null;
        }
        paused?.TrySetResult();
    }

    /// <summary>
    /// Fault injection: ends <see cref="StopAnswering"/> for exactly <paramref name="requests"/> more requests, then stops
    /// answering again (the rest stay buffered), like a robot halted part-way through what it was sent.
    /// </summary>
    public void ResumeAnswering(int requests)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(requests);
        Volatile.Write(ref _answerBudget, requests);
        ResumeAnswering();
    }

    /// <summary>Counts one executed request towards a pending <see cref="ResumeAnswering(int)"/>.</summary>
    private void CountTowardsPause()
    {
        int left = Volatile.Read(ref _answerBudget);
        if (left > 0 && Interlocked.CompareExchange(ref _answerBudget, left - 1, left) == left && left == 1)
        {
            StopAnswering();
        }
    }

    /// <summary>Holds the caller (the twin's program, at its acknowledgement) while the controller stops answering.</summary>
    private void WhileStopped(CancellationToken token) => TwinWait.WhilePaused(_pauseGate, ref _paused, token);

    /// <summary>Counts one delivered acknowledgement towards a pending <see cref="CloseConnectionAfter"/>.</summary>
    private void CountTowardsClose()
    {
        int left = Volatile.Read(ref _closeAfterAcknowledgements);
        if (left > 0 && Interlocked.CompareExchange(ref _closeAfterAcknowledgements, left - 1, left) == left && left == 1)
        {
            Volatile.Write(ref _closeAfterAcknowledgements, -1);
            DropClient();
        }
    }
}
