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

    /// <summary>A client of the controller at <paramref name="host"/> with <paramref name="options"/>.</summary>
    public RwsClient(string host, RobotWebServicesOptions options)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(host);
        ArgumentNullException.ThrowIfNull(options);
        _rws2 = options.UseRws2;
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
        HttpResponseMessage response;
        try
        {
            response = await _http.SendAsync(request, cancellationToken).ConfigureAwait(false);
        }
        catch (HttpRequestException ex)
        {
            throw new RobotWebServicesException(
                $"Could not {what}: the controller's Robot Web Services at {Address} did not answer ({ex.Message}). Check the address, " +
                "the port and that the computer is on the controller's network.", 0, null, ex);
        }
        catch (TaskCanceledException ex) when (!cancellationToken.IsCancellationRequested)
        {
            throw new RobotWebServicesException(
                $"Could not {what}: the controller's Robot Web Services at {Address} did not answer within {_http.Timeout.TotalSeconds.ToString(CultureInfo.InvariantCulture)} s.", 0, null, ex);
        }
        using (response)
        {
            string text = await response.Content.ReadAsStringAsync(cancellationToken).ConfigureAwait(false);
            if (response.IsSuccessStatusCode)
            {
                return text;
            }
            int status = (int)response.StatusCode;
            if (response.StatusCode == HttpStatusCode.Unauthorized)
            {
                throw new RobotWebServicesException(
                    $"Could not {what}: the controller refused the user name or password (HTTP 401). Set them in Robot.WebServices " +
                    "(or SetUser); the user needs the rights listed in docs/rws.md.", status, null);
            }
            (long? code, string? message) = RwsXhtml.Status(text);
            string reason = message ?? (text.Length > 0 ? RwsXhtml.Shorten(text) : response.ReasonPhrase ?? "no reason given");
            string codeText = code is { } c ? $", code {c.ToString(CultureInfo.InvariantCulture)}" : "";
            throw new RobotWebServicesException($"Could not {what}: the controller answered HTTP {status}{codeText}: {reason}", status, code);
        }
    }
}
