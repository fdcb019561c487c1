using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// One EthernetKRL channel of the twin, after EKI_Init: the robot listens (server) on its port and takes one client; each XML
/// document received is split into the value memories of its RECEIVE elements (all at once when the document is complete),
/// flags are set as configured, and EKI_Send writes the SEND elements whose values the program set.
/// </summary>
internal sealed partial class EkiChannel(string name, EkiConfiguration configuration, KrlTwinController controller) : IDisposable
{
    private readonly Lock _gate = new();

    /// <summary>
    /// Held while the connection changes together with the flags it writes (ALIVE, and a document's Set_Flag): EKI_Close and
    /// EKI_Clear return only once a disconnection under way has put its flag down, and a connection the channel let go of
    /// writes no flag after. Without it, a cleared channel's reader could put $FLAG[1] down after the next channel's client
    /// had put it up: the driver never saw that client, never greeted it and never listened again.
    /// </summary>
    private readonly Lock _link = new();
    private readonly Dictionary<string, EkiMemory> _memories = configuration.Receive
        .Where(e => e.Type is not null).ToDictionary(e => e.Tag, _ => new EkiMemory(), StringComparer.Ordinal);
    private readonly Dictionary<string, string> _toSend = new(StringComparer.Ordinal);
    private TcpListener? _listener;
    private TcpClient? _client;
    private EkiOutbox? _outbox;
    private CancellationTokenSource? _stop;
    private TcpListener? _reserved;

    /// <summary>The channel's name (its configuration file without .xml).</summary>
    public string Name { get; } = name;

    /// <summary>The configuration.</summary>
    public EkiConfiguration Configuration { get; } = configuration;

    /// <summary>True while a client is connected.</summary>
    public bool Connected
    {
        get
        {
            lock (_gate)
            {
                return _client is not null || _udpPeer is not null;
            }
        }
    }

    /// <summary>EKI_Open: the robot starts listening on <paramref name="port"/> (0: any free port, or its reserved socket); returns the port.</summary>
    public int Open(IPAddress address, int port)
    {
        if (Configuration.Udp)
        {
            return OpenUdp(address, port);
        }
        if (!Configuration.RobotIsServer)
        {
            return Connect();
        }
        TcpListener listener;
        CancellationToken stop;
        lock (_gate)
        {
            if (_listener is not null || _client is not null)
            {
                throw new KrlRuntimeException($"EthernetKRL: the channel {Name} is already open");
            }
            _stop = new CancellationTokenSource();
            stop = _stop.Token;
            _reserved = controller.Reserved(Name);
            if (_reserved is null)
            {
                _listener = new TcpListener(address, port);
                _listener.Start(1);
            }
            else
            {
                _listener = _reserved;
            }
            listener = _listener;
        }
        int bound = ((IPEndPoint)listener.LocalEndpoint).Port;
        // A client already waiting is connected before EKI_Open returns (the twin's choice among the orders a real network
        // allows: the program's next statement sees $FLAG of the connection); any other is accepted in the background.
        TcpClient? waiting = TakeWaiting(listener, stop);
        if (waiting is not null)
        {
            _ = Attach(listener, waiting, stop);
        }
        else
        {
            _ = Task.Run(() => AcceptAsync(listener, stop));
        }
        return bound;
    }

    /// <summary>A client waiting in the listener's queue that the seam accepts, or null (none waits, or it was refused).</summary>
    private TcpClient? TakeWaiting(TcpListener listener, CancellationToken token)
    {
        try
        {
            if (token.IsCancellationRequested || !listener.Pending())
            {
                return null;
            }
            TcpClient client = listener.AcceptTcpClient();
            client.NoDelay = true;
            if (controller.Options.Seam?.Accepted(this, client) != false)
            {
                return client;
            }
            client.Dispose();
            return null;
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException or InvalidOperationException)
        {
            return null;
        }
    }

    private async Task AcceptAsync(TcpListener listener, CancellationToken token)
    {
        TcpClient client;
        while (true)
        {
            try
            {
                client = await listener.AcceptTcpClientAsync(token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException or InvalidOperationException)
            {
                return;
            }
            client.NoDelay = true;
            if (token.IsCancellationRequested || controller.Options.Seam?.Accepted(this, client) != false)
            {
                break;
            }
            // Refused by the seam (a fault): closed at once, and the channel listens on.
            client.Dispose();
        }
        await Attach(listener, client, token).ConfigureAwait(false);
    }

    /// <summary>Makes <paramref name="client"/> the channel's connection (flag set before this returns) and reads it until it ends.</summary>
    private Task Attach(TcpListener? listener, TcpClient client, CancellationToken token)
    {
        lock (_link)
        {
            lock (_gate)
            {
                if (listener is not null && !ReferenceEquals(listener, _reserved))
                {
                    listener.Stop();
                }
                _listener = null;
                if (token.IsCancellationRequested)
                {
                    client.Dispose();
                    return Task.CompletedTask;
                }
                _client = client;
                _outbox = new EkiOutbox(client.GetStream());
            }
            Alive(true);
        }
        // A thread of its own that blocks in the socket's receive: each document wakes it once, where an asynchronous read woke
        // the socket engine's thread and then a thread-pool worker, which spun before it slept (issue 45).
        var done = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        var reader = new Thread(() =>
        {
            try
            {
                Read(client, token);
                done.TrySetResult();
            }
            catch (Exception e)
            {
                done.TrySetException(e); // as the task the reader ran in before
            }
        })
        {
            IsBackground = true,
            Name = "EKI " + Name,
        };
        reader.Start();
        return done.Task;
    }

    /// <summary>
    /// A splitter that hands each complete document (its values, the memory of each value, found once where the value is met, and
    /// the flags it sets) to <paramref name="commit"/>.
    /// </summary>
    private EkiXmlSplitter Splitter(Action<List<(string Tag, string Value)>, List<EkiMemory>, List<int>> commit)
    {
        var splitter = new EkiXmlSplitter(Configuration.BufferSize);
        var document = new List<(string Tag, string Value)>();
        var memories = new List<EkiMemory>();
        var flags = new List<int>();
        var frames = new Dictionary<string, string[]>(StringComparer.Ordinal);
        bool framed = FrameTags.Count > 0;
        // Without FRAME elements a tag's memory and a path's flags depend on the tag alone: found once per name, then by reference.
        var stored = new TagTable<EkiMemory?>();
        var flagged = new TagTable<int[]?>();
        splitter.Value += (tag, value) =>
        {
            EkiMemory? memory;
            if (framed)
            {
                if (FramePart(frames, tag, value) || !_memories.TryGetValue(tag, out memory) || FrameTags.Contains(tag))
                {
                    return;
                }
            }
            else if (!stored.TryGet(tag, out memory))
            {
                memory = _memories.GetValueOrDefault(tag);
                stored.Add(tag, memory);
            }
            if (memory is not null)
            {
                document.Add((tag, value));
                memories.Add(memory);
            }
        };
        splitter.Ended += (path, topLevel) =>
        {
            if (framed)
            {
                if (frames.Remove(path, out string[]? frame))
                {
                    document.Add((path, string.Join(' ', frame)));
                    memories.Add(_memories[path]);
                }
                else if (FrameTags.Contains(path))
                {
                    document.Add((path, "0 0 0 0 0 0")); // a FRAME element without components
                    memories.Add(_memories[path]);
                }
            }
            if (!flagged.TryGet(path, out int[]? set))
            {
                set = SetFlags.GetValueOrDefault(path);
                flagged.Add(path, set);
            }
            if (set is not null)
            {
                flags.AddRange(set);
            }
            if (topLevel)
            {
                commit(document, memories, flags);
            }
        };
        return splitter;
    }

    /// <summary>
    /// Reads the connection of <paramref name="client"/> until it ends. Compiled optimized at its first call: it runs once per
    /// connection, so it never reached the call count that has a method compiled again optimized, and its loop ran as first
    /// compiled until the runtime replaced it in the running loop (on-stack replacement), compiling it on this thread after
    /// some ten thousand receives, in whichever run of a stream that fell (50-150 ms of compiling in one run: 2-4 us per action
    /// of a 20,000-action run).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Read(TcpClient client, CancellationToken token)
    {
        // The channel's stop closes the socket, which ends a receive under way.
        using CancellationTokenRegistration stop = token.Register(static c => ((TcpClient)c!).Dispose(), client);
        // The flags of the documents of one arrival, set once they are all stored (see Raise).
        var raised = new List<int>();
        EkiXmlSplitter splitter = Splitter((document, memories, flags) => Commit(client, document, memories, flags, raised));
        EkiRawSplitter? raw = Configuration.RawReceive is { } element ? new EkiRawSplitter(element) : null;
        var bytes = new byte[8192];
        var decoder = Encoding.UTF8.GetDecoder();
        var chars = new char[Encoding.UTF8.GetMaxCharCount(bytes.Length)];
        try
        {
            // Null once the client was disposed (a channel closed before this thread ran).
            Socket? socket = client.Client;
            while (socket is not null && !token.IsCancellationRequested)
            {
                int n = socket.Receive(bytes);
                if (n == 0)
                {
                    break;
                }
                try
                {
                    if (raw is not null)
                    {
                        foreach (string record in raw.Append(bytes.AsSpan(0, n)))
                        {
                            Commit(client, RawDocument(record), null, RawFlags(), raised);
                        }
                        continue;
                    }
                    int count = decoder.GetChars(bytes, 0, n, chars, 0);
                    splitter.Append(chars.AsSpan(0, count));
                }
                finally
                {
                    Raise(client, raised); // also those of the documents before a malformed part: they were stored
                }
            }
        }
        catch (FormatException ex)
        {
            controller.Pendant.Log($"EthernetKRL {Name}: received {(raw is null ? "XML" : "binary data")} it cannot read ({ex.Message}); the connection is closed");
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            // The client left or the channel was closed.
        }
        Disconnect(client);
    }

    /// <summary>
    /// Sets the flags of the documents of one arrival (each flag once), after all of them are stored: the program waiting for a
    /// flag wakes once per arrival, as EthernetKRL hands an arrival's documents over together, and then finds every one of them
    /// (woken at the first, it ran beside the reader still storing the others, and was woken again for each). Under the link and
    /// only while <paramref name="client"/> is still the channel's connection, as the store: a program that closed or cleared the
    /// channel between the store and here let those documents go, and finds no flag of theirs up (before, the reader set it all
    /// the same, after EKI_Clear had returned).
    /// </summary>
    private void Raise(TcpClient client, List<int> raised)
    {
        if (raised.Count == 0)
        {
            return;
        }
        lock (_link)
        {
            if (IsClient(client))
            {
                foreach (int flag in raised)
                {
                    controller.SetFlag(flag, true);
                }
            }
        }
        raised.Clear();
    }

    /// <summary>
    /// Stores a complete document's values and keeps its flags in <paramref name="raised"/> for the end of the arrival (<see
    /// cref="Raise"/>; a memory over its limit sets them at once and closes the connection). A document that arrives on a
    /// connection the channel already let go of (closed, cleared) is lost, as on the controller.
    /// </summary>
    private void Commit(TcpClient client, List<(string Tag, string Value)> document, List<EkiMemory>? memories, List<int> flags, List<int> raised)
    {
        bool overflow = false;
        bool stored = false;
        // Under the link, as the connection's end: a document of a connection the channel already let go of reaches neither the
        // seam nor the memories. (Before, the seam could count such a document received after a program reset had closed the
        // channel and the next connection had attached, though the program never got it: the controller then held an action it
        // would log executed a second time at a later restart.)
        lock (_link)
        {
            if (IsClient(client))
            {
                // The seam sees the document before the program can take any of its values.
                controller.Options.Seam?.Received(this, CollectionsMarshal.AsSpan(document));
                overflow = Store(document, memories, null, dropExcess: false);
                stored = true;
            }
        }
        if (stored)
        {
            foreach (int flag in flags)
            {
                if (!raised.Contains(flag))
                {
                    raised.Add(flag);
                }
            }
        }
        document.Clear();
        memories?.Clear();
        flags.Clear();
        if (overflow)
        {
            Raise(client, raised);
            controller.Pendant.Log($"EthernetKRL {Name}: a memory holds more than {Configuration.Limit} elements; the connection is closed");
            // Only this reader's connection, which was still the channel's when its values were stored.
            client.Dispose();
        }
    }

    /// <summary>
    /// Stores a document's values in their memories (<paramref name="memories"/>, one per value, when the splitter found them; else
    /// by tag) and sets its flags (null: none here); true when a memory went over its limit.
    /// </summary>
    private bool Store(List<(string Tag, string Value)> document, List<EkiMemory>? memories, List<int>? flags, bool dropExcess)
    {
        bool overflow = false;
        lock (_gate)
        {
            for (int i = 0; i < document.Count; i++)
            {
                (string tag, string value) = document[i];
                EkiMemory memory = memories is null ? _memories[tag] : memories[i];
                if (dropExcess && memory.Count >= Configuration.Limit)
                {
                    overflow = true;
                    continue;
                }
                memory.AddLast(value);
                overflow |= memory.Count > Configuration.Limit;
            }
        }
        if (flags is not null)
        {
            foreach (int flag in flags)
            {
                controller.SetFlag(flag, true);
            }
        }
        return overflow;
    }

    /// <summary>
    /// Whether <paramref name="client"/> is still the channel's connection; call it under the link. The connection is set and
    /// cleared only under the link (<see cref="Attach"/>, <see cref="Disconnect"/>), so the link's holder reads it without the
    /// gate (the reader took the gate too, twice a document: once to store, once to raise its flags).
    /// </summary>
    private bool IsClient(TcpClient client) => ReferenceEquals(Volatile.Read(ref _client), client);

    /// <summary>Ends the connection of <paramref name="client"/> if it is still the channel's, its flag down before this returns.</summary>
    private void Disconnect(TcpClient client)
    {
        lock (_link)
        {
            lock (_gate)
            {
                if (_client != client)
                {
                    return;
                }
                _client = null;
                _outbox = null;
            }
            client.Dispose();
            controller.Options.Seam?.Closed(this, client);
            Alive(false);
        }
    }

    private void Alive(bool value)
    {
        if (Configuration.AliveFlag > 0)
        {
            controller.SetFlag(Configuration.AliveFlag, value);
        }
        else
        {
            controller.InputsChanged();
        }
    }

    /// <summary>How many elements the memory of <paramref name="tag"/> holds.</summary>
    public int Count(string tag)
    {
        lock (_gate)
        {
            return Memory(tag).Count;
        }
    }

    /// <summary>Takes the next element of the memory of <paramref name="tag"/> (null when empty); also returns how many remain.</summary>
    public string? Take(string tag, out int remaining) => Take(tag, out remaining, out _);

    /// <summary>
    /// <see cref="Take(string, out int)"/>, and whether a client is connected, read in the same look (an EKI_Get's status: one lock
    /// instead of two, ten times an action for the driver).
    /// </summary>
    public string? Take(string tag, out int remaining, out bool connected)
    {
        lock (_gate)
        {
            connected = _client is not null || _udpPeer is not null;
            EkiMemory memory = Memory(tag);
            if (memory.Count == 0)
            {
                remaining = 0;
                return null;
            }
            string value = Configuration.Fifo ? memory.TakeFirst() : memory.TakeLast();
            remaining = memory.Count;
            return value;
        }
    }

    /// <summary><see cref="Count(string)"/> and whether a client is connected, read in the same look (EKI_CheckBuffer's status).</summary>
    public int Count(string tag, out bool connected)
    {
        lock (_gate)
        {
            connected = _client is not null || _udpPeer is not null;
            return Memory(tag).Count;
        }
    }

    /// <summary>
    /// The tags the program named last, by reference, with their memories (guarded by the gate): a program names an element with
    /// a string literal, which the binder makes one string (<see cref="KrlBinder"/>), so the driver's twelve EKI_Get and
    /// EKI_CheckBuffer calls an action find their memory by a reference compare instead of hashing a 12- to 19-character tag.
    /// Tags made at run time (from a CHAR array) are other strings each time: they take the table's turn and replace the oldest.
    /// </summary>
    private readonly (string? Tag, EkiMemory? Memory)[] _named = new (string?, EkiMemory?)[32];
    private int _nextNamed;

    /// <summary>How many entries of the table are in use, and where the next look starts (guarded by the gate).</summary>
    private int _namedCount;
    private int _nextLook;

    /// <summary>The memory of <paramref name="tag"/> (call it under the gate); the program stops when the channel receives no such element.</summary>
    private EkiMemory Memory(string tag)
    {
        (string? Tag, EkiMemory? Memory)[] named = _named;
        // From the entry after the one found last: a program names its tags in the same order action after action (the driver's
        // EKI_CheckBuffer and ten EKI_Get), so the next one is found at the first look instead of after half the table.
        int count = _namedCount;
        for (int k = 0, i = _nextLook; k < count; k++, i = i + 1 == count ? 0 : i + 1)
        {
            if (ReferenceEquals(named[i].Tag, tag))
            {
                _nextLook = i + 1 == count ? 0 : i + 1;
                return named[i].Memory!;
            }
        }
        if (!_memories.TryGetValue(tag, out EkiMemory? memory))
        {
            throw new KrlRuntimeException($"EthernetKRL: the channel {Name} receives no element {tag} (see its RECEIVE configuration)");
        }
        named[_nextNamed] = (tag, memory);
        _nextNamed = (_nextNamed + 1) % named.Length;
        _namedCount = Math.Max(_namedCount, _nextNamed == 0 ? named.Length : _nextNamed);
        _nextLook = _nextNamed == 0 || _nextNamed >= _namedCount ? 0 : _nextNamed;
        return memory;
    }

    /// <summary>Whether the channel receives <paramref name="tag"/> or elements below it (its RECEIVE configuration).</summary>
    public bool Receives(string tag) => Configuration.Receive.Any(e => e.Tag == tag || e.Tag.StartsWith(tag + "/", StringComparison.Ordinal));

    /// <summary>
    /// EKI_ClearBuffer: empties the memories of <paramref name="tag"/> and of every element below it (a RECEIVE element that only
    /// sets a flag has no memory of its own); returns how many elements were dropped (none for a tag it does not receive).
    /// </summary>
    public int ClearBuffer(string tag)
    {
        int dropped = 0;
        lock (_gate)
        {
            foreach ((string memoryTag, EkiMemory memory) in _memories)
            {
                if (memoryTag == tag || memoryTag.StartsWith(tag + "/", StringComparison.Ordinal))
                {
                    dropped += memory.Count;
                    memory.Clear();
                }
            }
        }
        return dropped;
    }

    /// <summary>EKI_Set…: keeps the value of <paramref name="tag"/> for the next EKI_Send.</summary>
    public void Set(string tag, string value)
    {
        if (!SendTags.Contains(tag))
        {
            throw new KrlRuntimeException($"EthernetKRL: the channel {Name} sends no element {tag} (see its SEND configuration)");
        }
        lock (_gate)
        {
            _toSend[tag] = value;
        }
    }

    private HashSet<string>? _sendTags;

    /// <summary>The SEND configuration's tags.</summary>
    private HashSet<string> SendTags => _sendTags ??= new HashSet<string>(Configuration.Send, StringComparer.Ordinal);

    /// <summary>
    /// For each root EKI_Send named that the SEND configuration has: its attribute tags when it has only attributes, else null
    /// (written as a tree). Bounded by the configuration (data sent as it is is not kept); guarded by the gate.
    /// </summary>
    private readonly Dictionary<string, string[]?> _sendShapes = new(StringComparer.Ordinal);

    /// <summary>True when the SEND configuration has <paramref name="root"/> or an element or attribute below it.</summary>
    private bool Sends(string root)
    {
        IReadOnlyList<string> tags = Configuration.Send;
        for (int i = 0; i < tags.Count; i++)
        {
            if (tags[i] == root || EkiSendDocument.IsBelow(tags[i], root))
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>Where a flat document is written before it becomes its string (guarded by the gate).</summary>
    private char[] _sendText = new char[64];

    /// <summary>
    /// The UTF-8 bytes of the document EKI_Send writes for <paramref name="root"/> with the values set (call it under the gate): an
    /// element of attributes only (the driver's acknowledgement) goes from the channel's scratch to its bytes, without a string.
    /// </summary>
    private byte[] Document(string root)
    {
        if (!_sendShapes.TryGetValue(root, out string[]? attributes))
        {
            if (!Sends(root))
            {
                // Data sent as it is: XML (the manual's EKI_Send of "<Robot>…</Robot>") or plain text (EKI_Send("Channel", "Confirm")).
                return Encoding.UTF8.GetBytes(root);
            }
            attributes = EkiSendDocument.FlatAttributes(root, Configuration.Send);
            _sendShapes[root] = attributes;
        }
        return attributes is not null
            ? EkiSendDocument.WriteFlatBytes(root, attributes, _toSend, ref _sendText)
            : Encoding.UTF8.GetBytes(EkiSendDocument.Write(root, Configuration.Send, _toSend));
    }

    /// <summary>
    /// EKI_Send: writes the element <paramref name="root"/> with the values set for its attributes, or, when it names no configured
    /// element, <paramref name="root"/> itself as data (XML or plain text); in raw mode the data as a binary record (see
    /// <see cref="EkiRawSplitter.Record"/>). False without a client.
    /// </summary>
    public bool Send(string root)
    {
        EkiOutbox? outbox;
        byte[] bytes;
        lock (_gate)
        {
            // A string that names no configured element is data sent as it is: XML (the manual's EKI_Send of "<Robot>…</Robot>") or
            // plain text (EKI_Send("Channel", "Confirm")), which the twin writes unchanged rather than refuse.
            bytes = Configuration.RawSend is null ? Document(root) : [];
            outbox = _outbox;
        }
        IEkiSeam? seam = controller.Options.Seam;
        if (Configuration.RawSend is { } raw)
        {
            // The record's bytes, one a CHAR, to the seam too (before session 36 it was handed them read as Latin-1 and written
            // as UTF-8: a CHAR from 128 on went out as two bytes under `machina sim kuka`).
            bytes = EkiRawSplitter.Record(raw, root);
        }
        if (seam is not null)
        {
            // The seam sees every send, also one without a connection (it counts what was lost), and writes its own bytes.
            return seam.Send(this, root, bytes);
        }
        if (Configuration.Udp)
        {
            return SendDatagram(bytes);
        }
        // Handed to the channel's writer: the program goes on while it is written (in order, several sends in one write).
        return outbox is not null && outbox.Post(bytes);
    }

    /// <summary>Writes <paramref name="bytes"/> to the channel's client; false without one or when the connection broke.</summary>
    public bool SendDirect(ReadOnlySpan<byte> bytes)
    {
        TcpClient? client;
        lock (_gate)
        {
            client = _client;
        }
        if (client is null)
        {
            return false;
        }
        try
        {
            client.GetStream().Write(bytes);
            return true;
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or InvalidOperationException)
        {
            return false;
        }
    }

    /// <summary>Escapes a value for an XML attribute or element text.</summary>
    internal static string Escape(string value) => value.AsSpan().IndexOfAny("&<>\"") < 0 ? value : value.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal)
        .Replace(">", "&gt;", StringComparison.Ordinal).Replace("\"", "&quot;", StringComparison.Ordinal);

    /// <summary>
    /// EKI_Close: writes what EKI_Send queued, ends the connection and stops listening; the memories keep their elements. The
    /// wait for the queued sends ends when <paramref name="cancellation"/> is cancelled (the program stopped): the connection
    /// is ended all the same, and what was not written is lost.
    /// </summary>
    public void Close(CancellationToken cancellation = default)
    {
        controller.Sends.Flush(); // what the interpreter's sends hold on a held connection goes before the connection ends
        EkiOutbox? outbox;
        lock (_gate)
        {
            outbox = _outbox;
        }
        outbox?.Drain(cancellation);
        CloseUdp();
        // Under the link: a disconnection the reader began is finished (its flag down) before the channel counts as closed.
        lock (_link)
        {
            TcpClient? client;
            lock (_gate)
            {
                _stop?.Cancel();
                if (!ReferenceEquals(_listener, _reserved))
                {
                    _listener?.Stop();
                }
                _listener = null;
                client = _client;
            }
            if (client is not null)
            {
                Disconnect(client);
            }
        }
    }

    /// <summary>Formats a REAL as EKI_SetReal sends it.</summary>
    public static string Format(double value) => value.ToString("0.######", CultureInfo.InvariantCulture);

    /// <inheritdoc/>
    public void Dispose()
    {
        Close();
        _stop?.Dispose();
    }
}
