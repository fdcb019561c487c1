using System.Globalization;
using System.Net;
using System.Net.Http.Headers;
using System.Text;

namespace Machina;

/// <summary>
/// A client of an ABB controller's Robot Web Services (RWS 1.0: HTTP with digest authentication and a session cookie; RWS 2.0:
/// HTTPS with basic authentication), for what installing and watching Machina's driver needs. Every call can be cancelled; a
/// refusal throws <see cref="RobotWebServicesException"/> with the controller's reason.
/// </summary>
internal sealed partial class RwsClient : IDisposable
{
    private const string Rws2Media = "application/xhtml+xml;v=2.0";
    private const string Rws2Form = "application/x-www-form-urlencoded;v=2.0";
    private readonly HttpClient _http;
    private readonly bool _rws2;
    private readonly long _maxAnswer;

    /// <summary>A client of the controller at <paramref name="host"/> with <paramref name="options"/>.</summary>
    public RwsClient(string host, RobotWebServicesOptions options)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(host);
        ArgumentNullException.ThrowIfNull(options);
        _rws2 = options.UseRws2;
        _maxAnswer = options.MaxAnswerBytes;
        string scheme = _rws2 && !options.Rws2OverHttp ? "https" : "http";
        var address = new UriBuilder(scheme, host, options.Port ?? (_rws2 ? 443 : 80)).Uri;
        var credential = new NetworkCredential(options.UserName, options.Password);
        var handler = new SocketsHttpHandler
        {
            UseCookies = true,
            CookieContainer = new CookieContainer(),
            // RWS 1.0 asks for digest; the password is never sent as plain text over HTTP.
            Credentials = _rws2 ? null : new CredentialCache { { address, "Digest", credential } },
        };
        _http = new HttpClient(handler) { BaseAddress = address, Timeout = options.Timeout };
        if (_rws2)
        {
            string basic = Convert.ToBase64String(Encoding.UTF8.GetBytes(options.UserName + ":" + options.Password));
            _http.DefaultRequestHeaders.Authorization = new AuthenticationHeaderValue("Basic", basic);
            _http.DefaultRequestHeaders.Accept.Add(MediaTypeWithQualityHeaderValue.Parse(Rws2Media));
        }
        Address = address;
    }

    /// <summary>The controller's web address.</summary>
    public Uri Address { get; }

    /// <summary>GETs <paramref name="path"/> and returns the answer's text.</summary>
    public async Task<string> GetAsync(string path, string what, CancellationToken cancellationToken)
    {
        using var request = new HttpRequestMessage(HttpMethod.Get, path);
        return await SendAsync(request, what, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>POSTs the form <paramref name="fields"/> to <paramref name="path"/>.</summary>
    public async Task PostAsync(string path, string what, CancellationToken cancellationToken, params (string Name, string Value)[] fields)
    {
        using var request = new HttpRequestMessage(HttpMethod.Post, path);
        var content = new FormUrlEncodedContent(fields.Select(f => new KeyValuePair<string, string>(f.Name, f.Value)));
        if (_rws2)
        {
            content.Headers.ContentType = MediaTypeHeaderValue.Parse(Rws2Form);
        }
        request.Content = content;
        await SendAsync(request, what, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>PUTs <paramref name="text"/> (Latin-1, as RAPID files are) as the file <paramref name="path"/>.</summary>
    public async Task PutAsync(string path, string text, string what, CancellationToken cancellationToken)
    {
        using var request = new HttpRequestMessage(HttpMethod.Put, path);
        request.Content = new ByteArrayContent(Encoding.Latin1.GetBytes(text));
        request.Content.Headers.ContentType = new MediaTypeHeaderValue("text/plain");
        await SendAsync(request, what, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Closes the connections.</summary>
    public void Dispose() => _http.Dispose();

    private async Task<string> SendAsync(HttpRequestMessage request, string what, CancellationToken cancellationToken)
    {
        // One deadline for the whole exchange, the answer's body included (the client's own timeout ends at the headers).
        using var deadline = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        deadline.CancelAfter(_http.Timeout);
        HttpResponseMessage? response = null;
        try
        {
            response = await _http.SendAsync(request, HttpCompletionOption.ResponseHeadersRead, deadline.Token).ConfigureAwait(false);
            string text = await ReadAnswerAsync(response, what, deadline.Token).ConfigureAwait(false);
            return response.IsSuccessStatusCode ? text : throw Refusal(response, text, what);
        }
        catch (HttpRequestException ex)
        {
            throw new RobotWebServicesException(
                $"Could not {what}: the controller's Robot Web Services at {Address} did not answer ({PrintableText.Of(ex.Message)}). Check the address, " +
                "the port and that the computer is on the controller's network.", 0, null, ex);
        }
        catch (OperationCanceledException ex) when (!cancellationToken.IsCancellationRequested)
        {
            throw new RobotWebServicesException(
                $"Could not {what}: the controller's Robot Web Services at {Address} did not answer within {_http.Timeout.TotalSeconds.ToString(CultureInfo.InvariantCulture)} s.", 0, null, ex);
        }
        finally
        {
            response?.Dispose();
        }
    }

    /// <summary>
    /// The answer's text, read up to <see cref="RobotWebServicesOptions.MaxAnswerBytes"/>: a larger answer (declared or sent) is
    /// refused before it fills the memory of the process (a Rhino or Grasshopper session).
    /// </summary>
    private async Task<string> ReadAnswerAsync(HttpResponseMessage response, string what, CancellationToken cancellationToken)
    {
        if (response.Content.Headers.ContentLength is long declared && declared > _maxAnswer)
        {
            throw TooLarge(response, what, $"declares {declared.ToString(CultureInfo.InvariantCulture)} bytes");
        }
        Stream body = await response.Content.ReadAsStreamAsync(cancellationToken).ConfigureAwait(false);
        await using (body.ConfigureAwait(false))
        {
            using var kept = new MemoryStream();
            byte[] chunk = new byte[16 * 1024];
            int n;
            while ((n = await body.ReadAsync(chunk, cancellationToken).ConfigureAwait(false)) > 0)
            {
                if (kept.Length + n > _maxAnswer)
                {
                    throw TooLarge(response, what, "goes on past that");
                }
                kept.Write(chunk, 0, n);
            }
            return AnswerEncoding(response).GetString(kept.GetBuffer(), 0, (int)kept.Length);
        }
    }

    private RobotWebServicesException TooLarge(HttpResponseMessage response, string what, string how) => new(
        $"Could not {what}: the controller's answer (HTTP {((int)response.StatusCode).ToString(CultureInfo.InvariantCulture)}) {how}; Machina reads at most " +
        $"{_maxAnswer.ToString(CultureInfo.InvariantCulture)} bytes of an answer (Robot Web Services answers are a few kilobytes). Check the address: it may not be a controller.",
        (int)response.StatusCode, null);

    private static Encoding AnswerEncoding(HttpResponseMessage response)
    {
        string? charset = response.Content.Headers.ContentType?.CharSet?.Trim('"');
        try
        {
            return charset is null ? Encoding.UTF8 : Encoding.GetEncoding(charset);
        }
        catch (ArgumentException)
        {
            return Encoding.UTF8;
        }
    }

    /// <summary>The refusal of a request, with the controller's reason made printable (its text can carry escape codes).</summary>
    private static RobotWebServicesException Refusal(HttpResponseMessage response, string text, string what)
    {
        int status = (int)response.StatusCode;
        if (response.StatusCode == HttpStatusCode.Unauthorized)
        {
            return new RobotWebServicesException(
                $"Could not {what}: the controller refused the user name or password (HTTP 401). Set them in Robot.WebServices " +
                "(or SetUser); the user needs the rights listed in docs/rws.md.", status, null);
        }
        (long? code, string? message) = RwsXhtml.Status(text);
        string reason = message is not null ? PrintableText.Of(message)
            : text.Length > 0 ? RwsXhtml.Shorten(text) : PrintableText.Of(response.ReasonPhrase ?? "no reason given");
        string codeText = code is { } c ? $", code {c.ToString(CultureInfo.InvariantCulture)}" : "";
        return new RobotWebServicesException($"Could not {what}: the controller answered HTTP {status}{codeText}: {reason}", status, code);
    }
}
