using System.Text;

namespace Machina.Bridge;

/// <summary>The request line and headers of an HTTP/1.1 request, read strictly enough for a WebSocket handshake and a page.</summary>
internal sealed class HttpRequestHead
{
    /// <summary>Longest request head accepted, in bytes (request line and headers with their line ends).</summary>
    internal const int MaxBytes = 16 * 1024;

    /// <summary>Most header lines accepted.</summary>
    internal const int MaxHeaders = 100;

    private static readonly System.Buffers.SearchValues<char> TokenChars =
        System.Buffers.SearchValues.Create("!#$%&'*+-.^_`|~0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz");

    private readonly Dictionary<string, string> _headers;

    private HttpRequestHead(string method, string path, string query, Dictionary<string, string> headers)
    {
        Method = method;
        Path = path;
        Query = query;
        _headers = headers;
    }

    /// <summary>The method, e.g. <c>GET</c> (case-sensitive, as HTTP says).</summary>
    internal string Method { get; }

    /// <summary>The path of the target, still percent-encoded, e.g. <c>/Bridge</c>.</summary>
    internal string Path { get; }

    /// <summary>The query after <c>?</c>, without it; empty when none.</summary>
    internal string Query { get; }

    /// <summary>A header's value (repeated headers joined with ", "), or null. Names are case-insensitive.</summary>
    internal string? this[string name] => _headers.TryGetValue(name, out string? value) ? value : null;

    /// <summary>True when a comma-separated header holds <paramref name="token"/> (any letter case), e.g. Connection: keep-alive, Upgrade.</summary>
    internal bool HasToken(string name, string token) =>
        this[name] is string value && value.Split(',').Any(t => t.Trim().Equals(token, StringComparison.OrdinalIgnoreCase));

    /// <summary>The first value of a query parameter, percent-decoded ('+' is a space), or null when absent.</summary>
    internal string? QueryValue(string key)
    {
        foreach (string pair in Query.Split('&'))
        {
            int eq = pair.IndexOf('=', StringComparison.Ordinal);
            string k = Decode(eq < 0 ? pair : pair[..eq]);
            if (k == key)
            {
                return eq < 0 ? "" : Decode(pair[(eq + 1)..]);
            }
        }
        return null;
    }

    private static string Decode(string text) => Uri.UnescapeDataString(text.Replace('+', ' '));

    /// <summary>Reads a head (everything before the empty line, line ends CRLF or LF). Returns null and the reason when it is malformed.</summary>
    internal static HttpRequestHead? TryParse(ReadOnlySpan<byte> head, out string? error)
    {
        if (head.Length > MaxBytes)
        {
            error = "the request head is too long";
            return null;
        }
        // Latin-1 keeps every byte as one char, so that no byte sequence can fail to decode.
        string text = Encoding.Latin1.GetString(head);
        string[] lines = text.Split('\n');
        for (int i = 0; i < lines.Length; i++)
        {
            lines[i] = lines[i].EndsWith('\r') ? lines[i][..^1] : lines[i];
        }
        int count = lines.Length;
        while (count > 0 && lines[count - 1].Length == 0)
        {
            count--;
        }
        if (count == 0)
        {
            error = "the request is empty";
            return null;
        }
        string[] parts = lines[0].Split(' ');
        if (parts.Length != 3 || parts[0].Length == 0 || !parts[0].All(IsTokenChar))
        {
            error = "the request line is not 'METHOD /path HTTP/1.1'";
            return null;
        }
        if (parts[2] is not ("HTTP/1.1" or "HTTP/1.0"))
        {
            error = "only HTTP/1.1 is served";
            return null;
        }
        string target = parts[1];
        if (target.Length == 0 || target[0] != '/' || target.Any(c => c <= ' ' || c >= '\x7f'))
        {
            error = "the request target must be a path such as /Bridge";
            return null;
        }
        int hash = target.IndexOf('#', StringComparison.Ordinal);
        if (hash >= 0)
        {
            target = target[..hash];
        }
        int q = target.IndexOf('?', StringComparison.Ordinal);
        string path = q < 0 ? target : target[..q];
        string query = q < 0 ? "" : target[(q + 1)..];
        if (count - 1 > MaxHeaders)
        {
            error = "the request has too many headers";
            return null;
        }
        var headers = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        for (int i = 1; i < count; i++)
        {
            string line = lines[i];
            int colon = line.IndexOf(':', StringComparison.Ordinal);
            if (colon <= 0 || line.AsSpan(0, colon).ContainsAnyExcept(TokenChars))
            {
                error = $"header line {i} is not 'Name: value'";
                return null;
            }
            string value = line[(colon + 1)..].Trim(' ', '\t');
            if (value.Any(c => c < ' ' && c != '\t' || c == '\x7f'))
            {
                error = $"header line {i} holds a control character";
                return null;
            }
            string name = line[..colon];
            headers[name] = headers.TryGetValue(name, out string? before) ? before + ", " + value : value;
        }
        error = null;
        return new HttpRequestHead(parts[0], path, query, headers);
    }

    private static bool IsTokenChar(char c) => TokenChars.Contains(c);
}
