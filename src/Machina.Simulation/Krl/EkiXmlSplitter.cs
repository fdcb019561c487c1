using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// Reads the XML an external system sends on an EthernetKRL channel, as bytes arrive: element starts with their attributes,
/// element ends and text, each with its path (<c>DT/DR/A</c>). Whitespace between elements, declarations and comments are skipped.
/// </summary>
internal sealed class EkiXmlSplitter
{
    private readonly StringBuilder _pending = new();
    private readonly List<string> _path = [];

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
        if (_pending.Length > 1 << 20)
        {
            throw new FormatException("an XML element longer than 1 MB");
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
        Value?.Invoke(string.Join('/', _path), Decode(text.Trim()));
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
            if (_path.Count == 0 || _path[^1] != name)
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
        _path.Add(element);
        string path = string.Join('/', _path);
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

    private void End()
    {
        string path = string.Join('/', _path);
        _path.RemoveAt(_path.Count - 1);
        Ended?.Invoke(path, _path.Count == 0);
    }

    private static string Decode(string text) => text.Contains('&', StringComparison.Ordinal)
        ? text.Replace("&lt;", "<", StringComparison.Ordinal).Replace("&gt;", ">", StringComparison.Ordinal)
            .Replace("&quot;", "\"", StringComparison.Ordinal).Replace("&apos;", "'", StringComparison.Ordinal).Replace("&amp;", "&", StringComparison.Ordinal)
        : text;
}
