namespace Machina.Simulation.Krl;

/// <summary>
/// Writes the virtual KUKA's log text of a received action from its values: <c>&lt;A ID="1" T="3" …/&gt;</c>, each attribute
/// named by the last part of its tag, its value with &amp;, &lt;, &gt; and " written as XML's entities (the same text four
/// replacements gave: each character is replaced on its own, and no entity holds one of the four but its leading &amp;), a
/// value without them, as every number is, copied as it is. One buffer and the attribute names of the tags met (found by the
/// tag's reference: the channel's splitter hands the same string for a tag each time) are kept between actions, so an action
/// costs one string, where a builder appended each part, the name was cut from its tag and the whole copied again. The log
/// writes an action's text when it is first read (<see cref="EkiReceivedAction"/>). Not thread-safe: one reader uses it at a time.
/// </summary>
internal sealed class EkiReceivedText
{
    private char[] _buffer = new char[256];
    private int _length;

    /// <summary>The tags met with their attribute's opening (<c> V1="</c>); a tag made anew each time takes the oldest's place.</summary>
    private readonly (string? Tag, string Opening)[] _names = new (string?, string)[16];
    private int _next;

    /// <summary>The log text of one action's values (<paramref name="values"/>, one per tag of <paramref name="tags"/>).</summary>
    public string Of(ReadOnlySpan<string> tags, ReadOnlySpan<string> values)
    {
        _length = 0;
        Append("<A");
        for (int i = 0; i < tags.Length; i++)
        {
            Append(Opening(tags[i]));
            AppendEscaped(values[i]);
            Append("\"");
        }
        Append("/>");
        return new string(_buffer, 0, _length);
    }

    /// <summary>The attribute's opening of <paramref name="tag"/>: a space, the part after its last @ (the whole tag without one), =".</summary>
    private string Opening(string tag)
    {
        (string? Tag, string Opening)[] names = _names;
        for (int k = 0, i = _next; k < names.Length; k++, i = i + 1 == names.Length ? 0 : i + 1)
        {
            if (ReferenceEquals(names[i].Tag, tag))
            {
                _next = i + 1 == names.Length ? 0 : i + 1;
                return names[i].Opening;
            }
        }
        string opening = " " + tag[(tag.LastIndexOf('@') + 1)..] + "=\"";
        names[_next] = (tag, opening);
        _next = _next + 1 == names.Length ? 0 : _next + 1;
        return opening;
    }

    private void AppendEscaped(string value)
    {
        ReadOnlySpan<char> rest = value;
        int at;
        while ((at = rest.IndexOfAny("&<>\"")) >= 0)
        {
            Append(rest[..at]);
            Append(rest[at] switch
            {
                '&' => "&amp;",
                '<' => "&lt;",
                '>' => "&gt;",
                _ => "&quot;",
            });
            rest = rest[(at + 1)..];
        }
        Append(rest);
    }

    private void Append(ReadOnlySpan<char> text)
    {
        if (_length + text.Length > _buffer.Length)
        {
            Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + text.Length));
        }
        text.CopyTo(_buffer.AsSpan(_length));
        _length += text.Length;
    }
}
