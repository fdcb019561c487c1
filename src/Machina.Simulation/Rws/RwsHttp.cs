using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation.Rws;

/// <summary>One HTTP request as the twin's server reads it: method, path, query and form fields, headers and body.</summary>
internal sealed record RwsRequest(string Method, string Path, IReadOnlyDictionary<string, string> Query, IReadOnlyDictionary<string, string> Headers, byte[] Body)
{
    /// <summary>The body read as an HTML form (<c>name=value&amp;…</c>).</summary>
    public IReadOnlyDictionary<string, string> Form => RwsHttp.ParseForm(Encoding.Latin1.GetString(Body));

    /// <summary>The target exactly as the request line gave it (what digest authentication signs).</summary>
    public string Target { get; init; } = Path;
}

/// <summary>One HTTP response: status, extra headers and body.</summary>
internal sealed record RwsResponse(int Status, string Reason, byte[] Body, string ContentType = "application/xhtml+xml")
{
    /// <summary>Extra header lines (name, value).</summary>
    public List<(string Name, string Value)> Headers { get; } = [];

    /// <summary>No content (204).</summary>
    public static RwsResponse NoContent() => new(204, "No Content", []);
}

/// <summary>Reads requests from and writes responses to one connection (HTTP/1.1, Content-Length bodies, kept alive).</summary>
internal static class RwsHttp
{
    private const int MaxHeader = 16 * 1024;
    private const int MaxBody = 8 * 1024 * 1024;

    /// <summary>The next request on <paramref name="stream"/>, or null when the client closed the connection.</summary>
    public static async Task<RwsRequest?> ReadAsync(NetworkStream stream, CancellationToken cancellationToken)
    {
        var head = new List<byte>();
        var one = new byte[1];
        while (!EndsWithBlankLine(head))
        {
            if (await stream.ReadAsync(one, cancellationToken).ConfigureAwait(false) == 0)
            {
                return null;
            }
            head.Add(one[0]);
            if (head.Count > MaxHeader)
            {
                throw new InvalidDataException("The request's header is too long.");
            }
        }
        string[] lines = Encoding.Latin1.GetString([.. head]).Split("\r\n");
        string[] start = lines[0].Split(' ');
        if (start.Length < 3)
        {
            throw new InvalidDataException($"Not an HTTP request line: {lines[0]}");
        }
        var headers = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        foreach (string line in lines.Skip(1).Where(l => l.Length > 0))
        {
            int colon = line.IndexOf(':', StringComparison.Ordinal);
            if (colon > 0)
            {
                string name = line[..colon].Trim();
                string value = line[(colon + 1)..].Trim();
                headers[name] = headers.TryGetValue(name, out string? old) ? old + "; " + value : value;
            }
        }
        int length = headers.TryGetValue("Content-Length", out string? l) && int.TryParse(l, out int n) ? n : 0;
        if (length < 0 || length > MaxBody)
        {
            throw new InvalidDataException("The request's body is too long.");
        }
        byte[] body = new byte[length];
        await stream.ReadExactlyAsync(body, cancellationToken).ConfigureAwait(false);
        string target = start[1];
        int q = target.IndexOf('?', StringComparison.Ordinal);
        string path = Uri.UnescapeDataString(q < 0 ? target : target[..q]);
        IReadOnlyDictionary<string, string> query = q < 0 ? new Dictionary<string, string>() : ParseForm(target[(q + 1)..]);
        return new RwsRequest(start[0].ToUpperInvariant(), path, query, headers, body) { Target = target };
    }

    /// <summary>Writes <paramref name="response"/> to <paramref name="stream"/>.</summary>
    public static async Task WriteAsync(NetworkStream stream, RwsResponse response, CancellationToken cancellationToken)
    {
        var head = new StringBuilder();
        head.Append("HTTP/1.1 ").Append(response.Status).Append(' ').Append(response.Reason).Append("\r\n");
        head.Append("Content-Length: ").Append(response.Body.Length).Append("\r\n");
        if (response.Body.Length > 0)
        {
            head.Append("Content-Type: ").Append(response.ContentType).Append("\r\n");
        }
        foreach ((string name, string value) in response.Headers)
        {
            head.Append(name).Append(": ").Append(value).Append("\r\n");
        }
        head.Append("\r\n");
        await stream.WriteAsync(Encoding.Latin1.GetBytes(head.ToString()), cancellationToken).ConfigureAwait(false);
        await stream.WriteAsync(response.Body, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>The fields of a form or query (<c>a=1&amp;b=x%20y</c>).</summary>
    public static IReadOnlyDictionary<string, string> ParseForm(string text)
    {
        var fields = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        foreach (string pair in text.Split('&', StringSplitOptions.RemoveEmptyEntries))
        {
            int eq = pair.IndexOf('=', StringComparison.Ordinal);
            string name = Unescape(eq < 0 ? pair : pair[..eq]);
            fields[name] = eq < 0 ? "" : Unescape(pair[(eq + 1)..]);
        }
        return fields;
    }

    private static string Unescape(string text) => Uri.UnescapeDataString(text.Replace('+', ' '));

    private static bool EndsWithBlankLine(List<byte> b) =>
        b.Count >= 4 && b[^4] == '\r' && b[^3] == '\n' && b[^2] == '\r' && b[^1] == '\n';
}
