namespace Machina;

/// <summary>
/// A bounded queue between one reading thread and the one thread that consumes what it reads, whose waits block at once
/// instead of spinning first. A <c>BlockingCollection</c> spins and yields the processor on every wait: in a 10^6-line compile
/// the reader waits for the slower compiler some 240 times and yielded about 15,000 times, processor time for nothing.
/// </summary>
internal sealed class BatchHandOff<T> : IDisposable where T : class
{
    private readonly Queue<T> _items;
    private readonly int _capacity;
    private readonly CancellationToken _stop;
    private readonly CancellationTokenRegistration _wake;
    private readonly object _gate = new();
    private bool _completed;

    /// <summary>A queue of at most <paramref name="capacity"/> items; cancelling <paramref name="stop"/> wakes every wait.</summary>
    internal BatchHandOff(int capacity, CancellationToken stop)
    {
        _capacity = capacity;
        _items = new Queue<T>(capacity);
        _stop = stop;
        _wake = stop.Register(PulseAll);
    }

    /// <summary>Adds <paramref name="item"/>, waiting while the queue is full; throws when the stop token is cancelled.</summary>
    internal void Add(T item)
    {
        lock (_gate)
        {
            while (_items.Count >= _capacity)
            {
                _stop.ThrowIfCancellationRequested();
                Monitor.Wait(_gate);
            }
            _stop.ThrowIfCancellationRequested();
            _items.Enqueue(item);
            Monitor.PulseAll(_gate);
        }
    }

    /// <summary>
    /// Takes the next item, waiting while there is none; false when the queue is complete and empty. Throws when
    /// <paramref name="cancellationToken"/> (which must cancel the queue's stop token too) is cancelled.
    /// </summary>
    internal bool TryTake(out T item, CancellationToken cancellationToken)
    {
        lock (_gate)
        {
            while (_items.Count == 0)
            {
                cancellationToken.ThrowIfCancellationRequested();
                if (_completed)
                {
                    item = null!;
                    return false;
                }
                Monitor.Wait(_gate);
            }
            cancellationToken.ThrowIfCancellationRequested();
            item = _items.Dequeue();
            Monitor.PulseAll(_gate);
            return true;
        }
    }

    /// <summary>No more items will be added: a consumer waiting on an empty queue returns.</summary>
    internal void Complete()
    {
        lock (_gate)
        {
            _completed = true;
            Monitor.PulseAll(_gate);
        }
    }

    private void PulseAll()
    {
        lock (_gate)
        {
            Monitor.PulseAll(_gate);
        }
    }

    /// <inheritdoc/>
    public void Dispose() => _wake.Dispose();
}
