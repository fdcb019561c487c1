using System.Globalization;
using System.Net.Sockets;
using System.Text;
using System.Xml.Linq;
using Machina.Simulation.Rapid;
using static Machina.Simulation.Rws.RwsXhtmlWriter;

namespace Machina.Simulation.Rws;

/// <summary>
/// RWS 1.0 subscriptions: <c>POST /subscription</c> with <c>resources=1&amp;1=/rw/iosystem/signals/DO_1;state&amp;1-p=1</c> answers 201
/// with a <c>Location: ws://…/poll/N</c>; a WebSocket on it (protocol <c>robapi2_subscription</c>, the session's cookie) gets an
/// XHTML event each time one of the resources changes (looked at every 50 ms); <c>DELETE /subscription/N</c> ends it. The twin serves
/// IO signal states, the RAPID execution state, the panel's controller state, operating mode and speed ratio, the value of a PERS
/// (<c>/rw/rapid/symbol/data/RAPID/T_ROB1/module/name;value</c>: a <c>rap-value-ev</c> with the <c>rap-data</c> value) and the event
/// log (<c>/rw/elog/0</c>: one <c>elog-message-ev</c> with its <c>seqnum</c> per new message), as the RWS manual describes them.
/// </summary>
internal sealed partial class RwsTwinServer
{
    /// <summary>The most subscriptions kept at once (the twin's own number).</summary>
    public const int MaxSubscriptions = 64;

    /// <summary>How often a subscription's resources are looked at.</summary>
    private static readonly TimeSpan EventPeriod = TimeSpan.FromMilliseconds(50);

    private readonly Dictionary<int, string[]> _subscriptions = [];
    private int _nextSubscription;

    private RwsResponse Subscribe(IReadOnlyDictionary<string, string> form)
    {
        string[] resources = [.. form.Where(f => int.TryParse(f.Key, NumberStyles.None, CultureInfo.InvariantCulture, out _))
            .OrderBy(f => int.Parse(f.Key, CultureInfo.InvariantCulture)).Select(f => f.Value)];
        if (resources.Length == 0)
        {
            return Error(400, "Bad Request", null, "A subscription names its resources, e.g. resources=1&1=/rw/iosystem/signals/DO_1;state&1-p=1.");
        }
        if (resources.FirstOrDefault(r => Event(r) is null) is { } unknown)
        {
            return Error(400, "Bad Request", null, $"The twin serves no events of {unknown} (it serves /rw/iosystem/signals/NAME;state, " +
                "/rw/rapid/execution;ctrlexecstate, /rw/panel/ctrlstate, /rw/panel/opmode, /rw/panel/speedratio, " +
                "/rw/rapid/symbol/data/RAPID/TASK/MODULE/NAME;value of a PERS, and /rw/elog/0).");
        }
        int id;
        lock (_gate)
        {
            if (_subscriptions.Count >= MaxSubscriptions)
            {
                return Error(503, "Service Unavailable", null, $"{MaxSubscriptions} subscriptions are open, the most the twin keeps; delete one first.");
            }
            id = ++_nextSubscription;
            _subscriptions[id] = resources;
        }
        var created = new RwsResponse(201, "Created", []);
        created.Headers.Add(("Location", FormattableString.Invariant($"ws://127.0.0.1:{Port}/poll/{id}")));
        return created;
    }

    private RwsResponse Unsubscribe(string id)
    {
        lock (_gate)
        {
            return int.TryParse(id, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && _subscriptions.Remove(n)
                ? new RwsResponse(200, "OK", [])
                : Error(404, "Not Found", null, $"There is no subscription {id}.");
        }
    }

    /// <summary>The subscription a WebSocket request (<c>GET /poll/N</c> with <c>Upgrade: websocket</c>) asks for, or null for another request.</summary>
    private static int? PollOf(RwsRequest request) =>
        request.Method == "GET" && request.Path.StartsWith("/poll/", StringComparison.Ordinal)
        && string.Equals(request.Headers.GetValueOrDefault("Upgrade"), "websocket", StringComparison.OrdinalIgnoreCase)
        && int.TryParse(request.Path["/poll/".Length..], NumberStyles.None, CultureInfo.InvariantCulture, out int id) ? id : null;

    /// <summary>
    /// The event items of a resource as it is now (the first names the resource), or null when the twin serves no events of it; the
    /// event log's are none here: its messages come one by one (<see cref="ElogEvents"/>).
    /// </summary>
    private XElement[]? Event(string resource)
    {
        string[] parts = resource.Split(';', 2);
        string[] s = parts[0].Trim('/').Split('/');
        string? attribute = parts.Length > 1 ? parts[1] : null;
        XElement[]? items = (s, attribute) switch
        {
            (["rw", "iosystem", "signals", .., var name], "state") when Twin.Signal(name) is { } signal =>
                [Item("ios-signalstate-ev", name, ("lvalue", Text(SignalValue(signal))), ("lstate", "not simulated"))],
            (["rw", "rapid", "execution"], "ctrlexecstate") => [Item("rap-ctrlexecstate-ev", "ctrlexecstate", ("ctrlexecstate", Twin.IsRunning ? "running" : "stopped"))],
            (["rw", "panel", "ctrlstate"], null) => [Item("pnl-ctrlstate-ev", "ctrlstate", ("ctrlstate", MotorsOn ? "motoron" : "motoroff"))],
            (["rw", "panel", "opmode"], null) => [Item("pnl-opmode-ev", "opmode", ("opmode", OperationMode))],
            (["rw", "panel", "speedratio"], null) => [Item("pnl-speedratio-ev", "speedratio", ("speedratio", Text(SpeedRatio)))],
            (["rw", "rapid", "symbol", "data", "RAPID", var task, var module, var symbol], "value")
                when Twin.FindData(task, module, symbol) is { Storage: RapidStorage.Pers } cell && cell.Read(DataText) is { } value =>
                [Item("rap-value-ev", "value"), Item("rap-data", $"RAPID/{task}/{module}/{symbol}", ("value", value))],
            (["rw", "elog", "0"], null) => [],
            _ => null,
        };
        if (items is [var first, ..])
        {
            first.AddFirst(Link(resource, "self"));
        }
        return items;
    }

    /// <summary>True for the event log's resource, whose events are its new messages.</summary>
    private static bool IsElog(string resource) => resource.Trim('/') == "rw/elog/0";

    /// <summary>The sequence number of the newest event-log message (0: none yet).</summary>
    private int ElogNewest()
    {
        lock (_gate)
        {
            return _elog.Count == 0 ? 0 : _elog[^1].Sequence;
        }
    }

    /// <summary>One <c>elog-message-ev</c> per message newer than <paramref name="seen"/>, oldest first; <paramref name="seen"/> becomes the newest.</summary>
    private List<XElement> ElogEvents(ref int seen)
    {
        int after = seen;
        (int Sequence, int Code, string Title)[] fresh;
        lock (_gate)
        {
            fresh = [.. _elog.Where(e => e.Sequence > after)];
        }
        List<XElement> items = [];
        foreach ((int sequence, _, _) in fresh)
        {
            XElement item = Item("elog-message-ev", "", ("seqnum", Text(sequence)));
            item.Attribute("title")!.Remove();
            item.AddFirst(Link(FormattableString.Invariant($"/rw/elog/0/{sequence}"), "self"));
            items.Add(item);
            seen = sequence;
        }
        return items;
    }

    private static string Snapshot(XElement[]? items) => string.Concat((items ?? []).Select(i => i.ToString(SaveOptions.DisableFormatting)));

    private double SignalValue((string Bank, int Index) signal) =>
        signal.Bank[0] == 'd' ? (Twin.Io.GetBit(signal.Bank, signal.Index) ? 1 : 0) : Twin.Io.GetNumber(signal.Bank, signal.Index);

    /// <summary>
    /// Upgrades the connection to the subscription's WebSocket and sends an event each time one of its resources changes, until the
    /// client closes it, the subscription is deleted or the server stops.
    /// </summary>
    private async Task ServeSubscriptionAsync(NetworkStream stream, RwsRequest request, int id, CancellationToken cancellationToken)
    {
        string[]? resources;
        lock (_gate)
        {
            resources = _subscriptions.GetValueOrDefault(id);
        }
        if (resources is null || request.Headers.GetValueOrDefault("Sec-WebSocket-Key") is not { } key)
        {
            RwsResponse refusal = Error(resources is null ? 404 : 400, resources is null ? "Not Found" : "Bad Request", null,
                resources is null ? $"There is no subscription {id}." : "A WebSocket request has a Sec-WebSocket-Key.");
            refusal.Headers.Add(("Connection", "close"));
            await RwsHttp.WriteAsync(stream, refusal, cancellationToken).ConfigureAwait(false);
            return;
        }
        // What each resource is before the client may change anything: its items' text, or the event log's newest message.
        string[] last = [.. resources.Select(r => Snapshot(Event(r)))];
        int[] seen = [.. resources.Select(r => IsElog(r) ? ElogNewest() : 0)];
        string head = "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n" +
            $"Sec-WebSocket-Accept: {RwsWebSocket.AcceptKey(key)}\r\nSec-WebSocket-Protocol: robapi2_subscription\r\n\r\n";
        await stream.WriteAsync(Encoding.ASCII.GetBytes(head), cancellationToken).ConfigureAwait(false);
        using var ended = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        Task reading = ReadUntilCloseAsync(stream, ended);
        try
        {
            while (true)
            {
                await Task.Delay(EventPeriod, ended.Token).ConfigureAwait(false);
                lock (_gate)
                {
                    if (!_subscriptions.ContainsKey(id))
                    {
                        break;
                    }
                }
                List<XElement> changed = [];
                for (int i = 0; i < resources.Length; i++)
                {
                    if (IsElog(resources[i]))
                    {
                        changed.AddRange(ElogEvents(ref seen[i]));
                        continue;
                    }
                    XElement[] now = Event(resources[i]) ?? []; // a PERS whose module was unloaded: nothing to tell
                    string text = Snapshot(now);
                    if (text != last[i])
                    {
                        last[i] = text;
                        changed.AddRange(now);
                    }
                }
                if (changed.Count > 0)
                {
                    await RwsWebSocket.WriteAsync(stream, 1, EventDocument(id, changed), ended.Token).ConfigureAwait(false);
                }
            }
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            // The client closed the WebSocket.
        }
        await ended.CancelAsync().ConfigureAwait(false);
        await reading.ConfigureAwait(false);
        await RwsWebSocket.WriteAsync(stream, 8, [0x03, 0xE8], cancellationToken).ConfigureAwait(false); // close, 1000: normal
    }

    /// <summary>Reads the client's frames (keep-alive pongs, pings) until it closes the WebSocket or the connection ends; then cancels <paramref name="ended"/>.</summary>
    private static async Task ReadUntilCloseAsync(NetworkStream stream, CancellationTokenSource ended)
    {
        try
        {
            while (await RwsWebSocket.ReadAsync(stream, ended.Token).ConfigureAwait(false) is { } frame && frame.Opcode != 8)
            {
                // Nothing a subscriber sends besides a close needs an answer from the twin.
            }
        }
        catch (Exception ex) when (ex is IOException or SocketException or ObjectDisposedException or OperationCanceledException)
        {
            // The connection ended.
        }
        await ended.CancelAsync().ConfigureAwait(false);
    }
}
