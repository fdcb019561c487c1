using System.Buffers;
using System.Net;
using System.Net.Sockets;
using System.Net.WebSockets;
using System.Text;

namespace Machina.Bridge;

public sealed partial class BridgeServer
{
    private static readonly UTF8Encoding StrictUtf8 = new(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);

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
        int open = Interlocked.Increment(ref _connectionCount);
        string remote = tcp.Client.RemoteEndPoint?.ToString() ?? "?";
        try
        {
            tcp.NoDelay = true;
            NetworkStream stream = tcp.GetStream();
            if (open > _options.MaxConnections)
            {
                await WriteAsync(stream, HttpConnection.Error(503, "Service Unavailable", $"The bridge already serves {_options.MaxConnections} connections."), stop).ConfigureAwait(false);
                return;
            }
            HttpRequestHead? request = await ReadRequestAsync(stream, stop).ConfigureAwait(false);
            if (request is null)
            {
                return;
            }
            WebSocket? socket = await RouteAsync(request, stream, stop).ConfigureAwait(false);
            if (socket is not null)
            {
                using (socket)
                {
                    await ServeClientAsync(socket, request.QueryValue("name") is { Length: > 0 } name ? name : remote, remote).ConfigureAwait(false);
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
            Interlocked.Decrement(ref _connectionCount);
            tcp.Dispose();
        }
    }

    /// <summary>Reads the request head within the request timeout; answers and returns null when it is missing, too long or malformed.</summary>
    private async Task<HttpRequestHead?> ReadRequestAsync(NetworkStream stream, CancellationToken stop)
    {
        using var timeout = new CancellationTokenSource(_options.RequestTimeout, _options.TimeProvider);
        using var linked = CancellationTokenSource.CreateLinkedTokenSource(stop, timeout.Token);
        byte[]? head;
        bool tooLong;
        try
        {
            (head, tooLong) = await HttpConnection.ReadHeadAsync(stream, linked.Token).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (!stop.IsCancellationRequested)
        {
            await WriteAsync(stream, HttpConnection.Error(408, "Request Timeout", "The request did not arrive in time."), stop).ConfigureAwait(false);
            return null;
        }
        if (tooLong)
        {
            await WriteAsync(stream, HttpConnection.Error(431, "Request Header Fields Too Large", "The request head is too long."), stop).ConfigureAwait(false);
            return null;
        }
        if (head is null)
        {
            return null;
        }
        HttpRequestHead? request = HttpRequestHead.TryParse(head, out string? error);
        if (request is null)
        {
            await WriteAsync(stream, HttpConnection.Error(400, "Bad Request", $"Bad request: {error}."), stop).ConfigureAwait(false);
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
                "Content-Security-Policy: default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; connect-src 'self' ws: wss:; img-src data:\r\n",
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
        await WriteAsync(stream, HttpConnection.SwitchingProtocols(key!), stop).ConfigureAwait(false);
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

    private static async Task WriteAsync(NetworkStream stream, byte[] bytes, CancellationToken stop)
    {
        await stream.WriteAsync(bytes, stop).ConfigureAwait(false);
        await stream.FlushAsync(stop).ConfigureAwait(false);
    }

    /// <summary>Registers a WebSocket client, reads its messages until it leaves, and tells the others that it left.</summary>
    private async Task ServeClientAsync(WebSocket socket, string user, string remote)
    {
        var client = new BridgeClient(socket, user, _options.MaxQueuedEvents, OnClientOverflow);
        lock (_gate)
        {
            if (_state != 1)
            {
                return;
            }
            _clients = [.. _clients, client];
        }
        Robot.Logger.Info($"Bridge: client \"{user}\" connected from {remote}.");
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
