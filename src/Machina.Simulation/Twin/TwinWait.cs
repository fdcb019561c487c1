namespace Machina.Simulation.Twin;

/// <summary>
/// How a twin's own thread (an interpreter's, an EthernetKRL reader's) waits for a task it cannot go on without: a task already
/// complete costs nothing; otherwise the thread blocks until it completes or <c>cancellation</c> ends the wait, without the
/// spinning <see cref="Task.Wait()"/> and <c>GetAwaiter().GetResult()</c> do first (on a 2-core machine that spinning cost more
/// processor time per streamed action than the action itself, issue 45). The event is never asked for its wait handle, so it
/// holds no operating-system object and needs no disposing.
/// </summary>
internal static class TwinWait
{
    // What this thread does before it blocks: a RAPID task's held socket sends go out (TwinHeldSends). Per thread, set and cleared by
    // the thread itself, so two twins (each on threads of its own) never see each other's; null while nothing is held.
    [ThreadStatic]
    private static Action? t_beforeBlocking;

    /// <summary>
    /// Sets what the calling thread runs each time it is about to block in a twin's wait (<see cref="Blocking"/>), or clears it
    /// (null). Only for the calling thread.
    /// </summary>
    public static void BeforeBlocking(Action? action) => t_beforeBlocking = action;

    /// <summary>
    /// Called by every wait that blocks a twin's own thread, just before it blocks (not when what it waits for is already there):
    /// runs the thread's <see cref="BeforeBlocking"/> action, if any.
    /// </summary>
    public static void Blocking() => t_beforeBlocking?.Invoke();

    /// <summary>Waits for <paramref name="task"/> and rethrows its exception; <see cref="OperationCanceledException"/> when cancelled first.</summary>
    public static void For(Task task, CancellationToken cancellation)
    {
        if (!task.IsCompleted)
        {
            Block(task, Timeout.InfiniteTimeSpan, cancellation);
        }
        task.GetAwaiter().GetResult();
    }

    /// <summary>
    /// Waits while <paramref name="pause"/> (read under <paramref name="gate"/>; null: no pause) is not completed: a hold or a pause
    /// the thread must not run through. <see cref="OperationCanceledException"/> when cancelled first.
    /// </summary>
    public static void WhilePaused(Lock gate, ref TaskCompletionSource? pause, CancellationToken cancellation)
    {
        Task? wait;
        lock (gate)
        {
            wait = pause?.Task;
        }
        if (wait is not null)
        {
            For(wait, cancellation);
        }
    }

    /// <summary>Waits for <paramref name="task"/> and returns its result; <see cref="OperationCanceledException"/> when cancelled first.</summary>
    public static T For<T>(Task<T> task, CancellationToken cancellation)
    {
        if (!task.IsCompleted)
        {
            Block(task, Timeout.InfiniteTimeSpan, cancellation);
        }
        return task.GetAwaiter().GetResult();
    }

    /// <summary>
    /// Waits for <paramref name="task"/> at most <paramref name="timeout"/>; true when it ended (its exception is not thrown: look
    /// at the task). <see cref="OperationCanceledException"/> when cancelled first.
    /// </summary>
    public static bool For(Task task, TimeSpan timeout, CancellationToken cancellation)
    {
        cancellation.ThrowIfCancellationRequested();
        if (!task.IsCompleted)
        {
            Block(task, timeout, cancellation);
        }
        return task.IsCompleted;
    }

    /// <summary>Waits <paramref name="span"/> on <paramref name="time"/> (a test's clock steps it).</summary>
    public static void Delay(TimeSpan span, TimeProvider time, CancellationToken cancellation) =>
        For(Task.Delay(span, time, cancellation), cancellation);

    /// <summary>Blocks until the task ends or the timeout passes; throws when cancelled first.</summary>
    private static void Block(Task task, TimeSpan timeout, CancellationToken cancellation)
    {
        Blocking();
        if (task.IsCompleted)
        {
            return; // what the thread had held went out, and the answer to it came meanwhile
        }
        var done = new ManualResetEventSlim(false, spinCount: 0);
        task.ConfigureAwait(false).GetAwaiter().UnsafeOnCompleted(done.Set);
        done.Wait(timeout, cancellation);
    }
}
