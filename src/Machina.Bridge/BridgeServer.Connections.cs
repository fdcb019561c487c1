using System.Buffers;
using System.Net;
using System.Net.Sockets;
using System.Net.WebSockets;
using System.Text;

namespace Machina.Bridge;

public sealed partial class BridgeServer
{
    private static readonly UTF8Encoding StrictUtf8 = new(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);

    /// <summary>
    /// Headers of the page: it runs only its own inline script, talks only to WebSockets, may not be framed by any site
    /// (so that no other page can show it and make a person click in it), and sends no address on.
    /// </summary>
    internal const string PageHeaders =
        "Content-Security-Policy: default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; connect-src 'self' ws: wss:; img-src data:; frame-ancestors 'none'; form-action 'none'; base-uri 'none'\r\n" +
        "X-Frame-Options: DENY\r\nReferrer-Policy: no-referrer\r\nCross-Origin-Opener-Policy: same-origin\r\n";

    private async Task AcceptLoopAsync(CancellationToken stop)
    {
        while (!stop.IsCancellationRequested)
        {
            TcpClient tcp;
            try
            {
                tcp = await _listener!.AcceptTcpClientAsync(stop).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException or InvalidOperationException)
            {
                if (stop.IsCancellationRequested)
                {
                    return;
                }
                continue; // a connection that failed while being accepted
            }
            lock (_gate)
            {
                _connections.RemoveAll(t => t.IsCompleted);
                _connections.Add(Task.Run(() => ServeAsync(tcp, stop), CancellationToken.None));
            }
        }
    }

    /// <summary>Serves one TCP connection: one HTTP request, then, for a WebSocket, messages until either side closes.</summary>
    private async Task ServeAsync(TcpClient tcp, CancellationToken stop)
    {
        string remote = tcp.Client.RemoteEndPoint?.ToString() ?? "?";
        WebSocket? socket = null;
        try
        {
            tcp.NoDelay = true;
            NetworkStream stream = tcp.GetStream();
            (HttpRequestHead? request, socket) = await HandshakeAsync(stream, stop).ConfigureAwait(false);
            if (socket is not null)
            {
                using (socket)
                {
                    await ServeClientAsync(socket, request!.QueryValue("name") is { Length: > 0 } name ? name : remote, remote,
                        request.QueryValue("arm") == "1").ConfigureAwait(false);
                }
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException or WebSocketException)
        {
            // The client went away, or the bridge is stopping.
        }
        catch (Exception e)
        {
            Robot.Logger.Error($"Bridge: the connection from {remote} failed unexpectedly: {e}");
        }
        finally
        {
            if (socket is not null)
            {
                Interlocked.Decrement(ref _connectionCount); // its client slot, taken in RouteAsync
            }
            tcp.Dispose();
        }
    }

    /// <summary>
    /// Reads the request and answers it within <see cref="BridgeOptions.RequestTimeout"/>. Connections in their handshake do
    /// not take client slots; when there are more than <see cref="BridgeOptions.MaxPendingHandshakes"/>, the oldest is dropped.
    /// </summary>
    private async Task<(HttpRequestHead? Request, WebSocket? Socket)> HandshakeAsync(NetworkStream stream, CancellationToken stop)
    {
        using var deadline = new CancellationTokenSource(_options.RequestTimeout, _options.TimeProvider);
        using var linked = CancellationTokenSource.CreateLinkedTokenSource(stop, deadline.Token);
        LinkedListNode<CancellationTokenSource> node;
        CancellationTokenSource? evicted = null;
        lock (_gate)
        {
            node = _handshakes.AddLast(linked);
            if (_handshakes.Count > _options.MaxPendingHandshakes)
            {
                evicted = _handshakes.First!.Value;
                _handshakes.RemoveFirst();
            }
        }
        try
        {
            evicted?.Cancel();
        }
        catch (ObjectDisposedException)
        {
            // It finished meanwhile.
        }
        try
        {
            HttpRequestHead? request = await ReadRequestAsync(stream, linked.Token).ConfigureAwait(false);
            return request is null ? (null, null) : (request, await RouteAsync(request, stream, linked.Token).ConfigureAwait(false));
        }
        catch (OperationCanceledException) when (!stop.IsCancellationRequested)
        {
            byte[] answer = deadline.IsCancellationRequested
                ? HttpConnection.Error(408, "Request Timeout", "The request did not arrive in time.")
                : HttpConnection.Error(503, "Service Unavailable", "Too many connections are opening at once; try again.");
            await WriteAsync(stream, answer, stop).ConfigureAwait(false);
            return (null, null);
        }
        finally
        {
            lock (_gate)
            {
                if (node.List is not null)
                {
                    _handshakes.Remove(node);
                }
            }
        }
    }

    /// <summary>Reads the request head; answers and returns null when it is missing, too long or malformed.</summary>
    private static async Task<HttpRequestHead?> ReadRequestAsync(NetworkStream stream, CancellationToken cancellationToken)
    {
        (byte[]? head, bool tooLong) = await HttpConnection.ReadHeadAsync(stream, cancellationToken).ConfigureAwait(false);
        if (tooLong)
        {
            await WriteAsync(stream, HttpConnection.Error(431, "Request Header Fields Too Large", "The request head is too long."), cancellationToken).ConfigureAwait(false);
            return null;
        }
        if (head is null)
        {
            return null;
        }
        HttpRequestHead? request = HttpRequestHead.TryParse(head, out string? error);
        if (request is null)
        {
            await WriteAsync(stream, HttpConnection.Error(400, "Bad Request", $"Bad request: {error}."), cancellationToken).ConfigureAwait(false);
        }
        return request;
    }

    /// <summary>Answers a request: the page, an error, or the WebSocket handshake (then returns the socket).</summary>
    private async Task<WebSocket?> RouteAsync(HttpRequestHead request, NetworkStream stream, CancellationToken stop)
    {
        bool isSocketPath = string.Equals(request.Path.TrimEnd('/'), _options.Path.TrimEnd('/'), StringComparison.OrdinalIgnoreCase);
        bool isPage = request.Path is "/" or "/index.html";
        if (request.Method is not ("GET" or "HEAD"))
        {
            await WriteAsync(stream, HttpConnection.Error(405, "Method Not Allowed", "Only GET is served.", "Allow: GET, HEAD\r\n"), stop).ConfigureAwait(false);
            return null;
        }
        if (isPage && !isSocketPath)
        {
            byte[] response = HttpConnection.Response(200, "OK", "text/html; charset=utf-8", _page,
                PageHeaders,
                headOnly: request.Method == "HEAD");
            await WriteAsync(stream, response, stop).ConfigureAwait(false);
            return null;
        }
        if (!isSocketPath)
        {
            await WriteAsync(stream, HttpConnection.Error(404, "Not Found", $"Nothing here. The bridge's page is at / and its WebSocket at {_options.Path}."), stop).ConfigureAwait(false);
            return null;
        }
        if (!request.HasToken("Upgrade", "websocket") || !request.HasToken("Connection", "Upgrade") || request.Method != "GET")
        {
            await WriteAsync(stream, HttpConnection.Error(426, "Upgrade Required", $"This is the Machina Bridge's WebSocket: connect to ws://{request["Host"]}{_options.Path} with a WebSocket client.",
                "Upgrade: websocket\r\n"), stop).ConfigureAwait(false);
            return null;
        }
        if (request["Sec-WebSocket-Version"]?.Trim() != "13")
        {
            await WriteAsync(stream, HttpConnection.Error(426, "Upgrade Required", "Only WebSocket version 13 is spoken.", "Sec-WebSocket-Version: 13\r\n"), stop).ConfigureAwait(false);
            return null;
        }
        string? key = request["Sec-WebSocket-Key"]?.Trim();
        if (!HttpConnection.IsValidKey(key))
        {
            await WriteAsync(stream, HttpConnection.Error(400, "Bad Request", "Sec-WebSocket-Key must be 16 bytes in base64."), stop).ConfigureAwait(false);
            return null;
        }
        if (!IsAllowedOrigin(request))
        {
            Robot.Logger.Warning($"Bridge: refused a browser connection from the web page at {request["Origin"]} (allow it with the allowed origins setting).");
            await WriteAsync(stream, HttpConnection.Error(403, "Forbidden", $"Web pages from {request["Origin"]} may not drive this robot."), stop).ConfigureAwait(false);
            return null;
        }
        if (!HasToken(request))
        {
            Robot.Logger.Warning("Bridge: refused a connection without the bridge's token (authkey=…).");
            await WriteAsync(stream, HttpConnection.Error(403, "Forbidden", "This bridge needs its token: add authkey=TOKEN to the address, e.g. ws://HOST:PORT/Bridge?authkey=TOKEN."), stop).ConfigureAwait(false);
            return null;
        }
        if (Interlocked.Increment(ref _connectionCount) > _options.MaxConnections)
        {
            Interlocked.Decrement(ref _connectionCount);
            await WriteAsync(stream, HttpConnection.Error(503, "Service Unavailable", $"The bridge already serves {_options.MaxConnections} clients."), stop).ConfigureAwait(false);
            return null;
        }
        try
        {
            await WriteAsync(stream, HttpConnection.SwitchingProtocols(key!), stop).ConfigureAwait(false);
        }
        catch
        {
            Interlocked.Decrement(ref _connectionCount);
            throw;
        }
        return WebSocket.CreateFromStream(stream, new WebSocketCreationOptions
        {
            IsServer = true,
            KeepAliveInterval = TimeSpan.FromSeconds(30),
            KeepAliveTimeout = TimeSpan.FromSeconds(60), // a client that stops answering pings is dropped instead of holding a connection forever
        });
    }

    /// <summary>
    /// Clients that send no Origin are programs (Grasshopper, Python…) and are allowed; a browser always sends one, and only
    /// the bridge's own page (same host and port) and the configured origins may connect, so that a web site cannot drive the robot.
    /// </summary>
    private bool IsAllowedOrigin(HttpRequestHead request)
    {
        string? origin = request["Origin"]?.Trim();
        if (origin is null)
        {
            return true;
        }
        if (_options.AllowedOrigins.Any(o => o == "*" || string.Equals(o.TrimEnd('/'), origin, StringComparison.OrdinalIgnoreCase)))
        {
            return true;
        }
        if (!Uri.TryCreate(origin, UriKind.Absolute, out Uri? uri) || uri.Scheme != Uri.UriSchemeHttp)
        {
            return false;
        }
        // The page is served by this bridge when the origin names the address and port the request was sent to.
        return request["Host"] is string host && string.Equals(uri.Authority, host.Trim(), StringComparison.OrdinalIgnoreCase)
            && (uri.IsLoopback || IPAddress.TryParse(uri.Host.Trim('[', ']'), out _));
    }

    /// <summary>True when the bridge has no token, or the request's <c>authkey</c> parameter is it (compared in constant time).</summary>
    private bool HasToken(HttpRequestHead request)
    {
        if (_options.Token is not { } token)
        {
            return true;
        }
        string given = request.QueryValue("authkey") ?? "";
        return System.Security.Cryptography.CryptographicOperations.FixedTimeEquals(Encoding.UTF8.GetBytes(given), Encoding.UTF8.GetBytes(token));
    }

    private static async Task WriteAsync(NetworkStream stream, byte[] bytes, CancellationToken stop)
    {
        await stream.WriteAsync(bytes, stop).ConfigureAwait(false);
        await stream.FlushAsync(stop).ConfigureAwait(false);
    }

    /// <summary>
    /// Registers a WebSocket client, reads its messages until it leaves, and tells the others that it left. A client that asked
    /// for the arm (<c>?arm=1</c>, the bridge page) also gets the <c>arm</c> messages.
    /// </summary>
    private async Task ServeClientAsync(WebSocket socket, string user, string remote, bool wantsArm)
    {
        var client = new BridgeClient(socket, user, _options.MaxQueuedEvents, OnClientOverflow) { WantsArm = wantsArm };
        lock (_gate)
        {
            if (_state != 1)
            {
                return;
            }
            _clients = [.. _clients, client];
        }
        Robot.Logger.Info($"Bridge: client \"{user}\" connected from {remote}.");
        if (wantsArm && Robot.Model is RobotModel model && Robot.GetExecutedState().Axes is Joints joints)
        {
            client.Send(BridgeEvents.Arm(model.LinkPositions(joints)));   // where the arm is now, before it next moves
        }
        Task sending = Task.Run(() => client.RunSendLoopAsync(CancellationToken.None), CancellationToken.None);
        try
        {
            await ReceiveLoopAsync(client).ConfigureAwait(false);
        }
        finally
        {
            lock (_gate)
            {
                _clients = [.. _clients.Where(c => c != client)];
            }
            client.Close(WebSocketCloseStatus.NormalClosure, "");
            await CloseWithinAsync(client, sending).ConfigureAwait(false);
            Robot.Logger.Info($"Bridge: client \"{user}\" disconnected.");
            Broadcast(BridgeEvents.ClientDisconnected(user));
        }
    }

    /// <summary>Waits a few seconds for the close handshake to finish, then drops the connection.</summary>
    private async Task CloseWithinAsync(BridgeClient client, Task sending)
    {
        try
        {
            await sending.WaitAsync(CloseTimeout, _options.TimeProvider).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            client.Abort();
            await sending.ConfigureAwait(false);
        }
    }

    /// <summary>Reads whole messages (at most <see cref="BridgeOptions.MaxMessageBytes"/>) and handles each one in order.</summary>
    private async Task ReceiveLoopAsync(BridgeClient client)
    {
        WebSocket socket = client.Socket;
        byte[] chunk = ArrayPool<byte>.Shared.Rent(16 * 1024);
        var message = new ArrayBufferWriter<byte>(16 * 1024);
        bool tooLarge = false;
        try
        {
            while (true)
            {
                ValueWebSocketReceiveResult received = await socket.ReceiveAsync(chunk.AsMemory(), CancellationToken.None).ConfigureAwait(false);
                if (received.MessageType == WebSocketMessageType.Close)
                {
                    return;
                }
                if (!tooLarge)
                {
                    if (message.WrittenCount + received.Count > _options.MaxMessageBytes)
                    {
                        tooLarge = true;
                    }
                    else
                    {
                        message.Write(chunk.AsSpan(0, received.Count));
                    }
                }
                if (!received.EndOfMessage)
                {
                    continue;
                }
                HandleMessage(client, received.MessageType, tooLarge, message.WrittenSpan);
                tooLarge = false;
                if (message.Capacity > 256 * 1024)
                {
                    message = new ArrayBufferWriter<byte>(16 * 1024); // do not keep a large buffer per client
                }
                else
                {
                    message.ResetWrittenCount();
                }
            }
        }
        catch (Exception e) when (e is WebSocketException or IOException or OperationCanceledException or ObjectDisposedException)
        {
            // The client left without closing, broke the protocol, or was dropped by the bridge.
        }
        finally
        {
            ArrayPool<byte>.Shared.Return(chunk);
        }
    }

    /// <summary>Handles one complete message: every message gets at least one answer (events or an error) unless the bridge is stopping.</summary>
    private void HandleMessage(BridgeClient client, WebSocketMessageType type, bool tooLarge, ReadOnlySpan<byte> bytes)
    {
        if (type == WebSocketMessageType.Binary)
        {
            Reject(client, BridgeEvents.Error(BridgeEvents.Kinds.Frame, "Binary messages are not read; send instructions as text, such as MoveTo(400,300,500);"));
            return;
        }
        if (tooLarge)
        {
            Reject(client, BridgeEvents.Error(BridgeEvents.Kinds.Frame, $"The message is larger than {_options.MaxMessageBytes} bytes; send the program in several messages."));
            return;
        }
        string text;
        try
        {
            text = StrictUtf8.GetString(bytes);
        }
        catch (DecoderFallbackException)
        {
            Reject(client, BridgeEvents.Error(BridgeEvents.Kinds.Frame, "The message is not UTF-8 text."));
            return;
        }
        if (Controls.Of(text) is string control)
        {
            _ = ControlAsync(client, control);
            return;
        }
        FrameResult result;
        try
        {
            result = _frames.Handle(text);
        }
        catch (Exception e)
        {
            // Never expected: the handler turns every documented failure into a result. Keep serving, and say so.
            Robot.Logger.Error($"Bridge: handling a message from \"{client.User}\" failed unexpectedly: {e}");
            Reject(client, BridgeEvents.Error(BridgeEvents.Kinds.Internal, $"The bridge failed to handle this message ({e.GetType().Name}); nothing was issued."));
            return;
        }
        switch (result.Outcome)
        {
            case FrameOutcome.Rejected:
                Reject(client, result.Reply!);
                break;
            case FrameOutcome.NoController:
                Broadcast(result.Reply!);
                StartReconnecting();
                break;
        }
    }

    private void Reject(BridgeClient client, string reply)
    {
        Robot.Logger.Warning($"Bridge: refused a message from \"{client.User}\": {reply}");
        client.Send(reply);
    }

    /// <summary>Sends a message to every connected client, without waiting for any of them.</summary>
    private void Broadcast(string json)
    {
        BridgeClient[] clients;
        lock (_gate)
        {
            clients = _clients;
        }
        foreach (BridgeClient client in clients)
        {
            client.Send(json);
        }
    }

    private void OnClientOverflow(BridgeClient client)
    {
        Robot.Logger.Warning($"Bridge: client \"{client.User}\" did not read its events fast enough ({_options.MaxQueuedEvents} waiting) and was disconnected.");
        client.Abort();
    }
}
