using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// Reads the XML an external system sends on an EthernetKRL channel, as bytes arrive: element starts with their attributes,
/// element ends and text, each with its path (<c>DT/DR/A</c>). Whitespace between elements, declarations and comments are skipped.
/// Linear in what arrives: a document (a top-level element and what precedes it) is at most <paramref name="maxDocument"/>
/// characters (the channel's BUFFSIZE), elements nest at most <see cref="MaxDepth"/> deep, and each open element keeps its
/// whole path, so no path is joined again per element.
/// </summary>
internal sealed class EkiXmlSplitter(int maxDocument = EkiConfiguration.DefaultBufferSize)
{
    /// <summary>The deepest nesting of elements taken (docs/simulation.md, Network limits).</summary>
    public const int MaxDepth = 64;

    private readonly StringBuilder _pending = new();

    /// <summary>The path of each open element (<c>DT</c>, <c>DT/DR</c>, …), the innermost last.</summary>
    private readonly List<string> _path = [];

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

    /// <summary>Adds received text and reports every complete item; throws <see cref="FormatException"/> for malformed XML.</summary>
    public void Append(string text)
    {
        int at = 0;
        while (at < text.Length)
        {
            CheckDocument(at);
            if (_pending.Length > 0 && _pending[0] == '<')
            {
                int close = text.IndexOf('>', at);
                if (close < 0)
                {
                    _pending.Append(text, at, text.Length - at);
                    break;
                }
                _pending.Append(text, at, close - at);
                string tag = _pending.ToString(1, _pending.Length - 1);
                _pending.Clear();
                _tagEnd = close;
                Tag(tag);
                at = close + 1;
                continue;
            }
            int open = text.IndexOf('<', at);
            if (open < 0)
            {
                _pending.Append(text, at, text.Length - at);
                break;
            }
            if (open > at || _pending.Length > 0)
            {
                _pending.Append(text, at, open - at);
                string content = _pending.ToString();
                _pending.Clear();
                Text(content);
            }
            _pending.Append('<');
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

    private void Text(string text)
    {
        if (string.IsNullOrWhiteSpace(text))
        {
            return;
        }
        if (_path.Count == 0)
        {
            throw new FormatException($"text outside an element: \"{text.Trim()}\"");
        }
        Value?.Invoke(_path[^1], Decode(text.Trim()));
    }

    private void Tag(string body)
    {
        if (body.StartsWith('?') || body.StartsWith('!'))
        {
            return;
        }
        if (body.StartsWith('/'))
        {
            string name = body[1..].Trim();
            if (_path.Count == 0 || !ClosesInnermost(name))
            {
                throw new FormatException($"</{name}> does not close the open element");
            }
            End();
            return;
        }
        bool empty = body.EndsWith('/');
        if (empty)
        {
            body = body[..^1];
        }
        int i = 0;
        while (i < body.Length && !char.IsWhiteSpace(body[i]))
        {
            i++;
        }
        string element = body[..i];
        if (element.Length == 0)
        {
            throw new FormatException("an element without a name");
        }
        if (_path.Count == MaxDepth)
        {
            throw new FormatException($"elements nested more than {MaxDepth} deep");
        }
        string path = _path.Count == 0 ? element : _path[^1] + "/" + element;
        _path.Add(path);
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
            int equals = body.IndexOf('=', i);
            if (equals < 0 || equals + 1 >= body.Length || body[equals + 1] is not ('"' or '\''))
            {
                throw new FormatException($"a malformed attribute in <{element}>");
            }
            char quote = body[equals + 1];
            int end = body.IndexOf(quote, equals + 2);
            if (end < 0)
            {
                throw new FormatException($"an attribute of <{element}> is not closed");
            }
            Value?.Invoke(path + "/@" + body[i..equals].Trim(), Decode(body[(equals + 2)..end]));
            i = end + 1;
        }
        if (empty)
        {
            End();
        }
    }

    /// <summary>True when <paramref name="name"/> is the name of the innermost open element (the last part of its path).</summary>
    private bool ClosesInnermost(string name)
    {
        string path = _path[^1];
        return path.EndsWith(name, StringComparison.Ordinal) && (path.Length == name.Length || path[^(name.Length + 1)] == '/');
    }

    private void End()
    {
        string path = _path[^1];
        _path.RemoveAt(_path.Count - 1);
        if (_path.Count == 0)
        {
            _documentStart = _consumed + _tagEnd + 1;
        }
        Ended?.Invoke(path, _path.Count == 0);
    }

    private static string Decode(string text) => text.Contains('&', StringComparison.Ordinal)
        ? text.Replace("&lt;", "<", StringComparison.Ordinal).Replace("&gt;", ">", StringComparison.Ordinal)
            .Replace("&quot;", "\"", StringComparison.Ordinal).Replace("&apos;", "'", StringComparison.Ordinal).Replace("&amp;", "&", StringComparison.Ordinal)
        : text;
}
