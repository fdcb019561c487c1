namespace Machina.Simulation.Krl;

internal sealed partial class EkiChannel
{
    /// <summary>
    /// What the reader found for the tags and paths the splitter hands it, by the string's reference: the splitter gives a name it
    /// saw before as the same string (<see cref="EkiXmlSplitter"/>), and a stream sends the same names in the same order in every
    /// document, so the entry after the last one found is looked at first and a value's memory (or an element's flags) is found
    /// without hashing its 12- to 19-character tag. A tag that is a new string each time (beyond what the splitter keeps) takes
    /// the oldest entry's place; bounded, one per reader.
    /// </summary>
    private sealed class TagTable<T>
    {
        private readonly string?[] _tags = new string?[64];
        private readonly T[] _values = new T[64];
        private int _count;
        private int _next;
        private int _oldest;

        /// <summary>The value kept for <paramref name="tag"/> (the same string), or false.</summary>
        public bool TryGet(string tag, out T value)
        {
            int count = _count;
            for (int k = 0, i = _next; k < count; k++, i = i + 1 == count ? 0 : i + 1)
            {
                if (ReferenceEquals(_tags[i], tag))
                {
                    _next = i + 1 == count ? 0 : i + 1;
                    value = _values[i];
                    return true;
                }
            }
            value = default!;
            return false;
        }

        /// <summary>Keeps <paramref name="value"/> for <paramref name="tag"/> (after <see cref="TryGet"/> found none).</summary>
        public void Add(string tag, T value)
        {
            int at;
            if (_count < _tags.Length)
            {
                at = _count++;
            }
            else
            {
                at = _oldest;
                _oldest = (_oldest + 1) % _tags.Length;
            }
            _tags[at] = tag;
            _values[at] = value;
            _next = at + 1 == _count ? 0 : at + 1;
        }
    }
}
