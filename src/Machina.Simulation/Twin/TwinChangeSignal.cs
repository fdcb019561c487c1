namespace Machina.Simulation.Twin;

/// <summary>
/// Tells one reader that something it shows changed (a request logged or executed, a pendant text, an error, a signal written),
/// so that it sleeps while nothing does instead of looking on a timer: <c>machina sim</c>'s activity woke 20 times a second, and
/// with it the runtime's timer thread and two pool workers, about 200 thread wake-ups a second of an idle twin. A flag set by the
/// writers (<see cref="Changed"/>) and taken by the reader (<see cref="Take"/>), and a task for the reader to await while it is
/// not set (<see cref="WhenChangedAsync"/>). A write that finds the flag set already (a stream, while the reader waits before its
/// next look) costs a fence and a read of a line nobody writes.
/// </summary>
internal sealed class TwinChangeSignal
{
    private int _changed = 1; // the reader's first look tells what is there
    private TaskCompletionSource? _waiter;

    /// <summary>Marks a change and wakes the reader if it waits; call it after the change is written.</summary>
    public void Changed()
    {
        // The fence orders the change before the flag's read: a reader that takes the flag after this sees the change (it reads it
        // after its Exchange), and one that armed its wait before this is woken below.
        Interlocked.MemoryBarrier();
        ChangedAfterFence();
    }

    /// <summary>As <see cref="Changed"/>, right after an interlocked write of the change (itself a full fence).</summary>
    public void ChangedAfterFence()
    {
        if (Volatile.Read(ref _changed) == 0 && Interlocked.Exchange(ref _changed, 1) == 0
            && Volatile.Read(ref _waiter) is not null && Interlocked.Exchange(ref _waiter, null) is { } waiter)
        {
            waiter.TrySetResult();
        }
    }

    /// <summary>True while the reader sleeps on <see cref="WhenChangedAsync"/> (armed while the flag was clear, no change since).</summary>
    public bool IsAwaited => Volatile.Read(ref _waiter) is not null;

    /// <summary>Clears the flag before the reader looks: a change from now on sets it again. True when it was set.</summary>
    public bool Take() => Interlocked.Exchange(ref _changed, 0) == 1;

    /// <summary>
    /// Completes once the flag is set (at once when it is): the reader's sleep between two looks. One reader at a time: a wait
    /// armed before is released. <paramref name="cancellation"/> ends the wait (<see cref="OperationCanceledException"/>).
    /// </summary>
    public Task WhenChangedAsync(CancellationToken cancellation)
    {
        if (Volatile.Read(ref _changed) == 1)
        {
            return Task.CompletedTask;
        }
        var waiter = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        Interlocked.Exchange(ref _waiter, waiter)?.TrySetResult();
        // Armed first, the flag read after (both fenced): a change either sees the waiter or is seen here.
        if (Volatile.Read(ref _changed) == 1 && Interlocked.Exchange(ref _waiter, null) is { } armed)
        {
            armed.TrySetResult();
        }
        return waiter.Task.WaitAsync(cancellation);
    }
}
