namespace Machina.Simulation;

/// <summary>
/// The clients of one of the virtual UR's client interfaces (primary and secondary together, or real-time) and a wait for the
/// first of them. The interface's periodic sender runs its timer only while the group has a client: an idle controller wakes
/// no thread for it (the real-time interface ticks at 500 Hz, and every tick woke the timer thread and a thread-pool thread,
/// with or without a client: `machina sim ur` idle in URSim's layout spent 37 ms of processor time a second on it).
/// </summary>
internal sealed class VirtualUrClientGroup<T>
{
    private readonly Lock _gate = new();
    private readonly List<T> _clients = [];
    private TaskCompletionSource? _first;

    /// <summary>How many clients the group has now.</summary>
    public int Count
    {
        get
        {
            lock (_gate)
            {
                return _clients.Count;
            }
        }
    }

    /// <summary>Adds a client; a sender waiting for one goes on.</summary>
    public void Add(T client)
    {
        TaskCompletionSource? first;
        lock (_gate)
        {
            _clients.Add(client);
            (first, _first) = (_first, null);
        }
        first?.TrySetResult();
    }

    /// <summary>Removes a client (one that left or was dropped).</summary>
    public void Remove(T client)
    {
        lock (_gate)
        {
            _clients.Remove(client);
        }
    }

    /// <summary>The clients now (empty when none).</summary>
    public T[] Snapshot()
    {
        lock (_gate)
        {
            return _clients.Count == 0 ? [] : [.. _clients];
        }
    }

    /// <summary>Completes when the group has a client: at once when it has one; cancelled by <paramref name="cancellation"/>.</summary>
    public Task UntilAnyAsync(CancellationToken cancellation)
    {
        lock (_gate)
        {
            if (_clients.Count > 0)
            {
                return Task.CompletedTask;
            }
            _first ??= new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            return _first.Task.WaitAsync(cancellation);
        }
    }
}
