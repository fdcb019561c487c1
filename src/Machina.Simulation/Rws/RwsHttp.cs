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

/// <summary>A request the server refuses to read on (too long, malformed, too slow): the status and reason it answers before it closes.</summary>
internal sealed class RwsHttpRefusal(int status, string reason, string message) : Exception(message)
{
    /// <summary>The HTTP status (400, 408, 413, 431).</summary>
    public int Status { get; } = status;

    /// <summary>The HTTP reason phrase.</summary>
    public string Reason { get; } = reason;
}

/// <summary>
/// Reads requests from and writes responses to one connection (HTTP/1.1, Content-Length bodies, kept alive), with caps: a head
/// of at most <see cref="MaxHead"/> bytes, a body of at most <see cref="MaxBody"/>, a request complete within its deadline.
/// </summary>
internal static class RwsHttp
{
    /// <summary>The longest request head (request line and headers) read, in bytes.</summary>
    public const int MaxHead = 16 * 1024;

    /// <summary>The longest request body read, in bytes.</summary>
    public const int MaxBody = 8 * 1024 * 1024;

    /// <summary>
    /// The next request on <paramref name="stream"/>, or null when the client closed the connection or sent nothing for
    /// <paramref name="idle"/>. Once its first byte arrived, the request must be complete within <paramref name="deadline"/>.
    /// Throws <see cref="RwsHttpRefusal"/> for a request the server does not read on.
    /// </summary>
    public static async Task<RwsRequest?> ReadAsync(NetworkStream stream, TimeSpan idle, TimeSpan deadline, CancellationToken cancellationToken)
    {
        var one = new byte[1];
        using (var waiting = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken))
        {
            waiting.CancelAfter(idle);
            try
            {
                if (await stream.ReadAsync(one, waiting.Token).ConfigureAwait(false) == 0)
                {
                    return null;
                }
            }
            catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
            {
                return null;
            }
        }
        using var reading = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        reading.CancelAfter(deadline);
        try
        {
            return await ReadRestAsync(stream, one[0], reading.Token).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            throw new RwsHttpRefusal(408, "Request Timeout",
                $"The request was not complete within {deadline.TotalSeconds.ToString(System.Globalization.CultureInfo.InvariantCulture)} s of its first byte; the connection is closed.");
        }
    }

    private static async Task<RwsRequest?> ReadRestAsync(NetworkStream stream, byte first, CancellationToken cancellationToken)
    {
        var head = new List<byte> { first };
        var one = new byte[1];
        while (!EndsWithBlankLine(head))
        {
            if (await stream.ReadAsync(one, cancellationToken).ConfigureAwait(false) == 0)
            {
                return null;
            }
            head.Add(one[0]);
            if (head.Count > MaxHead)
            {
                throw new RwsHttpRefusal(431, "Request Header Fields Too Large", $"The request's head is longer than {MaxHead} bytes.");
            }
        }
        string[] lines = Encoding.Latin1.GetString([.. head]).Split("\r\n");
        string[] start = lines[0].Split(' ');
        if (start.Length != 3 || !start[2].StartsWith("HTTP/", StringComparison.Ordinal))
        {
            throw new RwsHttpRefusal(400, "Bad Request", $"Not an HTTP request line: {lines[0]}");
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
        long length = 0;
        if (headers.TryGetValue("Content-Length", out string? l)
            && !long.TryParse(l, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out length))
        {
            throw new RwsHttpRefusal(400, "Bad Request", $"The Content-Length \"{l}\" is not a number.");
        }
        if (length > MaxBody)
        {
            throw new RwsHttpRefusal(413, "Content Too Large", $"The request's body is longer than {MaxBody} bytes.");
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
        // Head and body in one write: two small writes would wait on the client's delayed acknowledgement.
        byte[] bytes = new byte[Encoding.Latin1.GetByteCount(head.ToString()) + response.Body.Length];
        int written = Encoding.Latin1.GetBytes(head.ToString(), bytes);
        response.Body.CopyTo(bytes, written);
        await stream.WriteAsync(bytes, cancellationToken).ConfigureAwait(false);
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
