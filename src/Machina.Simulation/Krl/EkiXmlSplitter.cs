using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// Reads the XML an external system sends on an EthernetKRL channel, as bytes arrive: element starts with their attributes,
/// element ends and text, each with its path (<c>DT/DR/A</c>). Whitespace between elements, declarations and comments are skipped.
/// Linear in what arrives: a document (a top-level element and what precedes it) is at most <paramref name="maxDocument"/>
/// characters (the channel's BUFFSIZE), elements nest at most <see cref="MaxDepth"/> deep, and each open element keeps its
/// whole path, so no path is joined again per element. A tag that arrives whole is read where it lies in the chunk, and the
/// paths of elements and attributes seen before are taken again instead of joined (a stream sends the same few names in
/// every document): only the values are new strings.
/// </summary>
internal sealed class EkiXmlSplitter(int maxDocument = EkiConfiguration.DefaultBufferSize)
{
    /// <summary>The deepest nesting of elements taken (docs/simulation.md, Network limits).</summary>
    public const int MaxDepth = 64;

    /// <summary>How many characters of names the splitter keeps for taking them again (beyond it, names are joined each time).</summary>
    private const int MaxKeptCharacters = 16_384;

    /// <summary>The most children and attributes one element keeps for taking them again.</summary>
    private const int MaxKeptPerElement = 64;

    /// <summary>Text between tags, or a tag's body (after its <c>&lt;</c>), begun in an earlier chunk.</summary>
    private readonly StringBuilder _pending = new();

    /// <summary>The open elements, the innermost last.</summary>
    private readonly List<Element> _path = [];

    /// <summary>The parent of the top-level elements (its path is empty).</summary>
    private readonly Element _root = new("", "");

    /// <summary>
    /// An attribute seen below an element: its name, its tag, and the value it had last (when short and without an entity), handed
    /// again while the same characters arrive: a stream repeats most values (the action type, the orientation, an empty message),
    /// so a document makes a string only for the values that changed.
    /// </summary>
    private sealed class KeptAttribute(string name, string tag)
    {
        public string Name { get; } = name;

        public string Tag { get; } = tag;

        public string? Last { get; set; }
    }

    /// <summary>The longest value an attribute keeps to hand again (longer ones are new strings each time).</summary>
    private const int MaxKeptValue = 64;

    /// <summary>Characters of the names kept in <see cref="Element"/>s.</summary>
    private int _keptCharacters;

    /// <summary>True while a tag is being read (its <c>&lt;</c> was seen, its <c>&gt;</c> not yet).</summary>
    private bool _inTag;

    /// <summary>Characters of the chunks before the current one.</summary>
    private long _consumed;

    /// <summary>Where the current document started (after the last complete top-level element), counted like <see cref="_consumed"/>.</summary>
    private long _documentStart;

    /// <summary>Where in the current chunk the tag being read ends.</summary>
    private int _tagEnd;

    /// <summary>An attribute or text value was read: tag (<c>DT/DR/A/@ID</c> or <c>DT/DR/A</c>) and value.</summary>
    public event Action<string, string>? Value;

    /// <summary>An element ended: its path; the second argument is true when it was a top-level element.</summary>
    public event Action<string, bool>? Ended;

    /// <summary>An element seen: its name and path, and the children and attribute tags met below it (kept to be taken again).</summary>
    private sealed class Element(string name, string path)
    {
        public string Name { get; } = name;

        public string Path { get; } = path;

        public List<Element> Children { get; } = [];

        public List<KeptAttribute> Attributes { get; } = [];

        /// <summary>Where the search for the next child starts: the one after the child found last (a stream repeats its order).</summary>
        public int NextChild { get; set; }

        /// <summary>Where the search for the next attribute starts: the one after the attribute found last.</summary>
        public int NextAttribute { get; set; }
    }

    /// <summary>Adds received text and reports every complete item; throws <see cref="FormatException"/> for malformed XML.</summary>
    public void Append(string text) => Append(text.AsSpan());

    /// <summary>Adds received text and reports every complete item; throws <see cref="FormatException"/> for malformed XML.</summary>
    public void Append(ReadOnlySpan<char> text)
    {
        int at = 0;
        while (at < text.Length)
        {
            CheckDocument(at);
            if (_inTag)
            {
                int close = text[at..].IndexOf('>');
                if (close < 0)
                {
                    _pending.Append(text[at..]);
                    break;
                }
                close += at;
                _tagEnd = close;
                _inTag = false;
                if (_pending.Length == 0)
                {
                    Tag(text[at..close]);
                }
                else
                {
                    _pending.Append(text[at..close]);
                    string body = _pending.ToString();
                    _pending.Clear();
                    Tag(body);
                }
                at = close + 1;
                continue;
            }
            int open = text[at..].IndexOf('<');
            if (open < 0)
            {
                _pending.Append(text[at..]);
                break;
            }
            open += at;
            if (_pending.Length > 0)
            {
                _pending.Append(text[at..open]);
                string content = _pending.ToString();
                _pending.Clear();
                Text(content);
            }
            else if (open > at)
            {
                Text(text[at..open]);
            }
            _inTag = true;
            at = open + 1;
        }
        CheckDocument(text.Length);
        _consumed += text.Length;
    }

    /// <summary>Throws when the document under way passed its size at <paramref name="at"/> in the current chunk.</summary>
    private void CheckDocument(int at)
    {
        if (_consumed + at - _documentStart > maxDocument)
        {
            throw new FormatException($"more than {maxDocument} bytes without a complete document (the channel's BUFFSIZE Limit)");
        }
    }

    private void Text(ReadOnlySpan<char> text)
    {
        if (text.IsWhiteSpace())
        {
            return;
        }
        if (_path.Count == 0)
        {
            throw new FormatException($"text outside an element: \"{text.Trim().ToString()}\"");
        }
        Value?.Invoke(_path[^1].Path, Decode(text.Trim()));
    }

    private void Tag(ReadOnlySpan<char> body)
    {
        if (body.Length > 0 && body[0] is ('?' or '!'))
        {
            return;
        }
        if (body.Length > 0 && body[0] == '/')
        {
            ReadOnlySpan<char> name = body[1..].Trim();
            if (_path.Count == 0 || !ClosesInnermost(name))
            {
                throw new FormatException($"</{name.ToString()}> does not close the open element");
            }
            End();
            return;
        }
        bool empty = body.Length > 0 && body[^1] == '/';
        if (empty)
        {
            body = body[..^1];
        }
        int i = 0;
        while (i < body.Length && !char.IsWhiteSpace(body[i]))
        {
            i++;
        }
        ReadOnlySpan<char> element = body[..i];
        if (element.Length == 0)
        {
            throw new FormatException("an element without a name");
        }
        if (_path.Count == MaxDepth)
        {
            throw new FormatException($"elements nested more than {MaxDepth} deep");
        }
        Element opened = Child(_path.Count == 0 ? _root : _path[^1], element);
        _path.Add(opened);
        while (true)
        {
            while (i < body.Length && char.IsWhiteSpace(body[i]))
            {
                i++;
            }
            if (i >= body.Length)
            {
                break;
            }
            int equals = body[i..].IndexOf('=');
            if (equals >= 0)
            {
                equals += i;
            }
            if (equals < 0 || equals + 1 >= body.Length || body[equals + 1] is not ('"' or '\''))
            {
                throw new FormatException($"a malformed attribute in <{element.ToString()}>");
            }
            char quote = body[equals + 1];
            int end = body[(equals + 2)..].IndexOf(quote);
            if (end < 0)
            {
                throw new FormatException($"an attribute of <{element.ToString()}> is not closed");
            }
            end += equals + 2;
            ReadOnlySpan<char> value = body[(equals + 2)..end];
            if (AttributeOf(opened, body[i..equals].Trim()) is { } attribute)
            {
                Value?.Invoke(attribute.Tag, Repeated(attribute, value));
            }
            else
            {
                Value?.Invoke(opened.Path + "/@" + body[i..equals].Trim().ToString(), Decode(value));
            }
            i = end + 1;
        }
        if (empty)
        {
            End();
        }
    }

    /// <summary>The element <paramref name="name"/> below <paramref name="parent"/>: one seen before, or a new one (kept while there is room).</summary>
    private Element Child(Element parent, ReadOnlySpan<char> name)
    {
        List<Element> children = parent.Children;
        int count = children.Count;
        for (int k = 0, i = parent.NextChild; k < count; k++, i = i + 1 == count ? 0 : i + 1)
        {
            Element child = children[i];
            if (name.SequenceEqual(child.Name))
            {
                parent.NextChild = i + 1 == count ? 0 : i + 1;
                return child;
            }
        }
        string text = name.ToString();
        var element = new Element(text, parent == _root ? text : parent.Path + "/" + text);
        if (parent.Children.Count < MaxKeptPerElement && Keep(element.Path.Length))
        {
            parent.Children.Add(element);
        }
        return element;
    }

    /// <summary>
    /// The attribute <paramref name="name"/> of <paramref name="element"/> (its tag <c>DT/DR/A/@ID</c>): one seen before, or a new
    /// one kept while there is room; null when there is none (the caller joins the tag itself).
    /// </summary>
    private KeptAttribute? AttributeOf(Element element, ReadOnlySpan<char> name)
    {
        List<KeptAttribute> attributes = element.Attributes;
        int count = attributes.Count;
        for (int k = 0, i = element.NextAttribute; k < count; k++, i = i + 1 == count ? 0 : i + 1)
        {
            KeptAttribute known = attributes[i];
            if (name.SequenceEqual(known.Name))
            {
                element.NextAttribute = i + 1 == count ? 0 : i + 1;
                return known;
            }
        }
        string text = name.ToString();
        string joined = element.Path + "/@" + text;
        if (element.Attributes.Count < MaxKeptPerElement && Keep(joined.Length))
        {
            var attribute = new KeptAttribute(text, joined);
            element.Attributes.Add(attribute);
            return attribute;
        }
        return null;
    }

    /// <summary>The value <paramref name="raw"/> of <paramref name="attribute"/>: the string it had last when the characters are the same, else decoded anew (and kept when short and without an entity).</summary>
    private static string Repeated(KeptAttribute attribute, ReadOnlySpan<char> raw)
    {
        if (attribute.Last is { } last && raw.SequenceEqual(last))
        {
            return last;
        }
        string value = Decode(raw);
        attribute.Last = raw.Length <= MaxKeptValue && !raw.Contains('&') ? value : null;
        return value;
    }

    /// <summary>True (and counted) when <paramref name="characters"/> more fit in what the splitter keeps.</summary>
    private bool Keep(int characters)
    {
        if (_keptCharacters + characters > MaxKeptCharacters)
        {
            return false;
        }
        _keptCharacters += characters;
        return true;
    }

    /// <summary>True when <paramref name="name"/> is the name of the innermost open element (the last part of its path).</summary>
    private bool ClosesInnermost(ReadOnlySpan<char> name)
    {
        string path = _path[^1].Path;
        return path.AsSpan().EndsWith(name, StringComparison.Ordinal) && (path.Length == name.Length || path[^(name.Length + 1)] == '/');
    }

    private void End()
    {
        string path = _path[^1].Path;
        _path.RemoveAt(_path.Count - 1);
        if (_path.Count == 0)
        {
            _documentStart = _consumed + _tagEnd + 1;
        }
        Ended?.Invoke(path, _path.Count == 0);
    }

    private static string Decode(ReadOnlySpan<char> text) => text.Contains('&')
        ? text.ToString().Replace("&lt;", "<", StringComparison.Ordinal).Replace("&gt;", ">", StringComparison.Ordinal)
            .Replace("&quot;", "\"", StringComparison.Ordinal).Replace("&apos;", "'", StringComparison.Ordinal).Replace("&amp;", "&", StringComparison.Ordinal)
        : text.ToString();
}
