namespace Machina.Simulation;

/// <summary>
/// One of a virtual controller's logs (requests received, ids executed, pendant texts, errors): its last entries, oldest first,
/// in a ring that grows up to its capacity, and how many it was ever given (<see cref="Total"/>), so that a reader who polls it
/// copies only what came since its last read (<see cref="CopySince"/>) instead of the whole log. Not thread-safe: the controller
/// writes and copies under its lock; <see cref="Total"/> alone may be read without it.
/// </summary>
/// <typeparam name="T">The entries.</typeparam>
internal sealed class VirtualControllerLog<T>(int capacity)
{
    private T[] _ring = [];
    private int _first;
    private int _count;
    private long _total;

    /// <summary>How many entries were ever added (also those no longer kept); read without the lock (an atomic read).</summary>
    public long Total => Volatile.Read(ref _total);

    /// <summary>Adds an entry, dropping the oldest when the log holds <c>capacity</c> already (keeps none at capacity 0).</summary>
    public void Add(T entry)
    {
        if (capacity > 0)
        {
            if (_count < capacity && _count == _ring.Length)
            {
                Grow();
            }
            if (_count < capacity)
            {
                _ring[(_first + _count++) % _ring.Length] = entry;
            }
            else
            {
                _ring[_first] = entry;
                _first = (_first + 1) % _ring.Length;
            }
        }
        Volatile.Write(ref _total, _total + 1); // one writer at a time (the controller's lock)
    }

    /// <summary>
    /// Adds to <paramref name="into"/> the entries still kept among those added after the first <paramref name="seen"/> ever added,
    /// oldest first, and returns <see cref="Total"/>: the <paramref name="seen"/> of the next read.
    /// </summary>
    public long CopySince(long seen, ICollection<T> into)
    {
        for (int k = FirstSince(seen); k < _count; k++)
        {
            into.Add(_ring[(_first + k) % _ring.Length]);
        }
        return _total;
    }

    /// <summary>How many entries are kept (at most the capacity).</summary>
    public int Count => _count;

    /// <summary>
    /// Where the first kept entry added after the first <paramref name="seen"/> ever added is, as an index for <see cref="At"/>
    /// (<see cref="Count"/> when there is none).
    /// </summary>
    public int FirstSince(long seen)
    {
        long fresh = _total - Math.Max(seen, 0);
        return fresh >= _count ? 0 : _count - (int)Math.Max(fresh, 0);
    }

    /// <summary>
    /// The kept entry <paramref name="k"/> (0 the oldest kept, below <see cref="Count"/>), by reference: a reader may replace it
    /// in place (the request log keeps the text it wrote for an entry there, so that it is written once).
    /// </summary>
    public ref T At(int k) => ref _ring[(_first + k) % _ring.Length];

    /// <summary>The entries kept, oldest first.</summary>
    public T[] ToArray()
    {
        var all = new T[_count];
        for (int k = 0; k < _count; k++)
        {
            all[k] = _ring[(_first + k) % _ring.Length];
        }
        return all;
    }

    /// <summary>Doubles the ring (up to the capacity), the entries from its start.</summary>
    private void Grow()
    {
        var larger = new T[Math.Min(capacity, Math.Max(16, _ring.Length * 2))];
        for (int k = 0; k < _count; k++)
        {
            larger[k] = _ring[(_first + k) % _ring.Length];
        }
        _ring = larger;
        _first = 0;
    }
}
