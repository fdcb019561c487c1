namespace Machina.Simulation.Krl;

/// <summary>
/// The value memory of one RECEIVE element of an EthernetKRL channel: its elements in the order received, taken from the front
/// (FIFO) or the back (LIFO). A ring of strings that grows by doubling and is reused, so that storing and taking a value
/// allocates nothing (a linked list made a node per value). Not thread-safe: the channel guards it.
/// </summary>
internal sealed class EkiMemory
{
    private string[] _items = new string[16];
    private int _first;

    /// <summary>How many elements it holds.</summary>
    public int Count { get; private set; }

    /// <summary>Stores <paramref name="value"/> after the others.</summary>
    public void AddLast(string value)
    {
        if (Count == _items.Length)
        {
            var larger = new string[_items.Length * 2];
            for (int i = 0; i < Count; i++)
            {
                larger[i] = _items[(_first + i) % _items.Length];
            }
            _items = larger;
            _first = 0;
        }
        _items[(_first + Count) % _items.Length] = value;
        Count++;
    }

    /// <summary>Takes the oldest element (the memory must not be empty).</summary>
    public string TakeFirst()
    {
        string value = _items[_first];
        _items[_first] = null!;
        _first = (_first + 1) % _items.Length;
        Count--;
        return value;
    }

    /// <summary>Takes the newest element (the memory must not be empty).</summary>
    public string TakeLast()
    {
        int last = (_first + Count - 1) % _items.Length;
        string value = _items[last];
        _items[last] = null!;
        Count--;
        return value;
    }

    /// <summary>Forgets every element.</summary>
    public void Clear()
    {
        Array.Clear(_items);
        _first = 0;
        Count = 0;
    }
}
