namespace Machina.Simulation.Twin;

/// <summary>
/// Waits on a twin's own thread for a task (a socket's receive, an accept) without spinning: <c>Task.Wait</c> spins the
/// processor before it blocks, which a twin that waits once per streamed action paid on every action. This is a kernel wait
/// on the task's handle and the cancellation's.
/// </summary>
internal static class TwinTaskWait
{
    /// <summary>Blocks until <paramref name="operation"/> ends or <paramref name="timeout"/> passes; true when it ended. Throws when cancelled.</summary>
    public static bool For(Task operation, TimeSpan timeout, CancellationToken cancellation)
    {
        cancellation.ThrowIfCancellationRequested();
        if (!operation.IsCompleted)
        {
            WaitHandle.WaitAny([((IAsyncResult)operation).AsyncWaitHandle, cancellation.WaitHandle], timeout);
            cancellation.ThrowIfCancellationRequested();
        }
        return operation.IsCompleted;
    }
}
