using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Rapid;

namespace Machina.Simulation.Rws;

/// <summary>
/// Robot Web Services 1.0 of a RAPID twin, on its own loopback port: digest authentication with a session cookie, and the
/// resources Machina's installer and a user need (panel, RAPID execution, tasks and data, files, mastership, event log,
/// mechanical unit targets, IO signals), acting on the twin itself. A test sets the operating mode, the motors, the speed
/// ratio and who else holds mastership.
/// </summary>
internal sealed partial class RwsTwinServer : IAsyncDisposable
{
    private readonly TcpListener _listener = new(IPAddress.Loopback, 0);
    private readonly CancellationTokenSource _stop = new();
    private readonly List<TcpClient> _clients = [];
    private readonly Lock _gate = new();
    private readonly RwsNonces _nonces;
    private readonly HashSet<string> _sessions = [];
    private readonly Queue<string> _sessionOrder = new();
    private readonly string _user;
    private readonly string _password;
    private Task? _accepting;

    /// <summary>
    /// A server for <paramref name="twin"/> accepting <paramref name="user"/> with <paramref name="password"/> (ABB's default user by
    /// default); with <paramref name="rws2"/>, what RWS 2.0 changes for a client: basic authentication and the <c>v=2.0</c> media
    /// types (over plain HTTP: the twin serves no TLS).
    /// </summary>
    /// <param name="twin">The twin the services act on.</param>
    /// <param name="user">The one user.</param>
    /// <param name="password">Its password.</param>
    /// <param name="rws2">True to speak RWS 2.0.</param>
    /// <param name="time">The clock of the nonces' lifetime (the system's by default; a test's manual clock).</param>
    public RwsTwinServer(RapidTwinController twin, string user = "Default User", string password = "robotics", bool rws2 = false, TimeProvider? time = null)
    {
        _nonces = new RwsNonces(time ?? TimeProvider.System);
        Twin = twin;
        Rws2 = rws2;
        _user = user;
        _password = password;
        twin.TaskEnded += task =>
        {
            if (task.Error is { } error)
            {
                Log(LeadingCode(error), error);
            }
        };
        twin.EventLogged += Log;
    }

    /// <summary>True when the server speaks RWS 2.0 (basic authentication, <c>v=2.0</c> media types).</summary>
    public bool Rws2 { get; }

    /// <summary>The twin the services act on.</summary>
    public RapidTwinController Twin { get; }

    /// <summary>The loopback port (after <see cref="Start"/>).</summary>
    public int Port => ((IPEndPoint)_listener.LocalEndpoint).Port;

    /// <summary>The operating mode the panel reports: AUTO (default), MANR or MANF.</summary>
    public string OperationMode { get; set; } = "AUTO";

    /// <summary>True (default) when the motors are on.</summary>
    public bool MotorsOn { get; set; } = true;

    /// <summary>The speed ratio in percent (default 100).</summary>
    public int SpeedRatio { get; set; } = 100;

    /// <summary>Who else holds mastership (e.g. "FlexPendant"), or null when nobody does.</summary>
    public string? MastershipHeldBy { get; set; }

    /// <summary>How long a digest nonce is taken after the server handed it out (default 5 minutes; then the client is told it is stale).</summary>
    public TimeSpan NonceLifetime
    {
        get => _nonces.Lifetime;
        set => _nonces.Lifetime = value;
    }

    /// <summary>How long a client may take to send a request's head and body once it started it (default 10 s; then 408 and the connection closes).</summary>
    public TimeSpan RequestDeadline { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>How long a connection may stay idle between requests before the server closes it (default 5 minutes).</summary>
    public TimeSpan IdleDeadline { get; set; } = TimeSpan.FromMinutes(5);

    /// <summary>Starts listening and serving.</summary>
    public void Start()
    {
        _listener.Start();
        _accepting = AcceptAsync(_stop.Token);
    }

    /// <summary>Stops serving and closes every connection.</summary>
    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        _listener.Stop();
        lock (_gate)
        {
            _clients.ForEach(c => c.Dispose());
            _clients.Clear();
        }
        if (_accepting is not null)
        {
            await _accepting.ConfigureAwait(false);
        }
        _stop.Dispose();
    }

    private async Task AcceptAsync(CancellationToken cancellationToken)
    {
        while (!cancellationToken.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await _listener.AcceptTcpClientAsync(cancellationToken).ConfigureAwait(false);
            }
            catch (Exception ex) when (ex is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                return;
            }
            client.NoDelay = true;
            if (!_connections.TryEnter())
            {
                await RefuseAsync(client, cancellationToken).ConfigureAwait(false);
                continue;
            }
            lock (_gate)
            {
                _clients.Add(client);
            }
            _ = ServeAsync(client, cancellationToken);
        }
    }

    private async Task ServeAsync(TcpClient client, CancellationToken cancellationToken)
    {
        try
        {
            NetworkStream stream = client.GetStream();
            while (true)
            {
                RwsRequest? request;
                try
                {
                    request = await RwsHttp.ReadAsync(stream, IdleDeadline, RequestDeadline, cancellationToken).ConfigureAwait(false);
                }
                catch (RwsHttpRefusal refusal)
                {
                    // A request the server cannot read is answered, then the connection closes (what follows it cannot be framed).
                    RwsResponse answer = RwsXhtmlWriter.Error(refusal.Status, refusal.Reason, null, refusal.Message);
                    answer.Headers.Add(("Connection", "close"));
                    await RwsHttp.WriteAsync(stream, answer, cancellationToken).ConfigureAwait(false);
                    return;
                }
                if (request is null)
                {
                    return;
                }
                RwsResponse? refused = Authenticate(request, out string? session, out bool opened) ?? MediaRefusal(request);
                if (refused is null && PollOf(request) is int subscription)
                {
                    await ServeSubscriptionAsync(stream, request, subscription, cancellationToken).ConfigureAwait(false);
                    return; // the WebSocket ended the connection
                }
                RwsResponse response = refused ?? Handle(request, session!);
                if (opened)
                {
                    response.Headers.Add(("Set-Cookie", $"-http-session-={session}; path=/; httponly"));
                    response.Headers.Add(("Set-Cookie", $"ABBCX={session}; path=/; httponly"));
                }
                await RwsHttp.WriteAsync(stream, response, cancellationToken).ConfigureAwait(false);
            }
        }
        catch (Exception ex) when (ex is IOException or SocketException or ObjectDisposedException or OperationCanceledException)
        {
            // The client or the server closed the connection.
        }
        finally
        {
            lock (_gate)
            {
                _clients.Remove(client);
            }
            client.Dispose();
            _connections.Leave();
        }
    }

    /// <summary>Null with the session when the request is authenticated (a session cookie, or a right digest answer that opens one); else a 401 challenge.</summary>
    private RwsResponse? Authenticate(RwsRequest request, out string? session, out bool opened)
    {
        opened = false;
        string? cookie = request.Headers.GetValueOrDefault("Cookie")?.Split(';').Select(c => c.Trim())
            .FirstOrDefault(c => c.StartsWith("-http-session-=", StringComparison.Ordinal))?["-http-session-=".Length..];
        lock (_gate)
        {
            if (cookie is not null && _sessions.Contains(cookie))
            {
                session = cookie;
                return null;
            }
            string? authorization = request.Headers.GetValueOrDefault("Authorization");
            RwsNonceState digest = Rws2 ? RwsNonceState.Unknown
                : RwsDigest.Verify(authorization, request.Method, request.Target, _user, _password, _nonces);
            if (Rws2 ? RwsBasic.Verify(authorization, _user, _password) : digest == RwsNonceState.Fresh)
            {
                session = RwsDigest.NewNonce();
                OpenSession(session);
                opened = true;
                return null;
            }
            session = null;
            var challenge = RwsXhtmlWriter.Error(401, "Unauthorized", null, "Authentication required.");
            if (Rws2)
            {
                challenge.Headers.Add(("WWW-Authenticate", "Basic realm=\"RWS\""));
                return challenge;
            }
            challenge.Headers.Add(("WWW-Authenticate", RwsDigest.Challenge(_nonces.Issue(), stale: digest == RwsNonceState.Stale)));
            return challenge;
        }
    }

    /// <summary>The most sessions kept at once (a log-on past it ends the oldest session, whose client logs on again).</summary>
    public const int MaxSessions = 1024;

    private void OpenSession(string session)
    {
        while (_sessionOrder.Count >= MaxSessions)
        {
            _sessions.Remove(_sessionOrder.Dequeue());
        }
        _sessions.Add(session);
        _sessionOrder.Enqueue(session);
    }

    /// <summary>RWS 2.0: a 406 when the client does not accept the v=2.0 XHTML, a 415 when its form is not the v=2.0 one; else null.</summary>
    private RwsResponse? MediaRefusal(RwsRequest request)
    {
        if (!Rws2)
        {
            return null;
        }
        if (!(request.Headers.GetValueOrDefault("Accept") ?? "").Contains("v=2.0", StringComparison.Ordinal))
        {
            return RwsXhtmlWriter.Error(406, "Not Acceptable", null, "RWS 2.0 answers application/xhtml+xml;v=2.0 (or application/hal+json;v=2.0); the request's Accept does not ask for it.");
        }
        if (request.Method == "POST" && request.Body.Length > 0
            && !(request.Headers.GetValueOrDefault("Content-Type") ?? "").Contains("v=2.0", StringComparison.Ordinal))
        {
            return RwsXhtmlWriter.Error(415, "Unsupported Media Type", null, "RWS 2.0 takes forms as application/x-www-form-urlencoded;v=2.0.");
        }
        return null;
    }

    private static int LeadingCode(string error) =>
        int.TryParse(error.Split(' ', 2)[0], System.Globalization.NumberStyles.Integer, System.Globalization.CultureInfo.InvariantCulture, out int code) ? code : 0;
}
