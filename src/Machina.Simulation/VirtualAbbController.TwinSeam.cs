using System.Globalization;
using System.Net.Sockets;
using System.Runtime.CompilerServices;
using System.Text;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Simulation;

/// <summary>
/// The virtual ABB's faults and inspection when it runs RAPID, at the seams a real controller has: the driver task's socket.
/// The connection its SocketAccept takes becomes the driver connection (refused by the fault plan as a busy network would);
/// each statement its SocketReceive reads is a request received (counted, logged, buffered until acknowledged); its SocketSend
/// of an acknowledgement (<c>@id code;</c>, or <c>code;</c> for id 0) is what its arm just executed: on the driver task's own
/// thread, that write goes through the fault plan (held while the controller stops answering, delayed, cut, lost, followed by
/// a drop) and is counted as executed, with no hand-off to another thread. Everything else it sends (handshake, information,
/// failure reports) and the monitor task's sockets go straight to the connection. Every write goes through the connection's
/// outbox (<see cref="TwinHeldOutbox"/>): what a task sends is held until it waits, then written at once.
/// </summary>
public sealed partial class VirtualAbbController : IRapidSocketSeam
{
    private readonly Queue<TwinRequest> _awaiting = new();
    private readonly StringBuilder _statement = new();
    private bool _inText;
    private Socket? _driverSocket;
    private RapidInbox? _driverInbox;
    private Socket? _monitorSocket;

    /// <summary>A request the driver task read, from the client of <paramref name="generation"/>; its acknowledgement once the driver writes one.</summary>
    private sealed class TwinRequest(int id, int generation)
    {
        public int Id { get; } = id;

        public int Generation { get; } = generation;

        /// <summary>The acknowledgement the driver wrote for it; null: none goes to the host (skipped, or run while nobody listened).</summary>
        public byte[]? Acknowledgement { get; set; }
    }

    private readonly ConnectionLog _connections;

    bool IRapidSocketSeam.Accepted(int localPort, Socket connection, Stream outbox, CancellationToken task)
    {
        if (localPort == Port || localPort == MonitorPort)
        {
            _connections.Connected(localPort == Port ? "driver" : "monitor", connection, connection);
        }
        if (localPort != Port)
        {
            if (localPort == MonitorPort)
            {
                lock (Gate)
                {
                    _monitorSocket = connection;
                }
            }
            return true;
        }
        if (IsRestarting || task.IsCancellationRequested)
        {
            _connections.Left(connection);
            connection.Dispose();
            return false; // the program a restart stops greets no one: the host connects again to the one that starts
        }
        TwinRequest[] orphans;
        lock (Gate)
        {
            _driverSocket = connection;
            _statement.Clear();
            _inText = false;
            orphans = [.. _awaiting];
            _awaiting.Clear();
            _driverInbox = null;
        }
        // The driver accepts again only once it ran everything it read (its ReadRequests found the link closed): what the last client
        // sent and was not acknowledged ran while nobody listened. It counts as executed, without an acknowledgement.
        foreach (TwinRequest orphan in orphans)
        {
            CompleteReceivedOnCaller(orphan, Math.Max(orphan.Id, 0), orphan.Generation, runs: true, task);
        }
        var client = new TcpClient();
        client.Client.Dispose();
        client.Client = connection;
        if (!AttachClient(client, outbox))
        {
            _connections.Left(connection);
            return false;
        }
        var inbox = new RapidInbox();
        lock (Gate)
        {
            _driverInbox = inbox;
        }
        RunOnThread(token => ReadDriver(connection, inbox, token));
        return true;
    }

    void IRapidSocketSeam.Closed(Socket connection, CancellationToken task)
    {
        _connections.Left(connection);
        TwinRequest[] ran;
        lock (Gate)
        {
            if (!ReferenceEquals(connection, _driverSocket))
            {
                return;
            }
            ran = [.. _awaiting];
            _awaiting.Clear();
        }
        // The driver reads only once it ran what it read: finding the link closed, it ran every request it read, and those it
        // could not acknowledge (the link was gone) ran while nobody listened. They count as executed, without an acknowledgement.
        foreach (TwinRequest r in ran)
        {
            CompleteReceivedOnCaller(r, Math.Max(r.Id, 0), r.Generation, runs: true, task);
        }
    }

    RapidInbox? IRapidSocketSeam.Inbox(Socket connection)
    {
        lock (Gate)
        {
            return ReferenceEquals(connection, _driverSocket) ? _driverInbox : null;
        }
    }

    void IRapidSocketSeam.Received(Socket connection, string text, CancellationToken task)
    {
        // The driver's connection is read by ReadDriverAsync; the monitor's receives nothing the controller counts.
    }

    /// <summary>
    /// Reads the driver connection as data arrives, as a controller's network stack does: each statement is counted received
    /// (and buffered until its acknowledgement) on arrival, and the text waits in <paramref name="inbox"/> until the driver's
    /// SocketReceive takes it, 80 characters at a time. When the host closes, what arrived stays readable. On a thread of its own,
    /// blocked in the socket's receive (the controller's stop closes the socket).
    /// </summary>
    // Optimized at its first call: it runs once per connection, so it would run as first compiled until replaced in the running loop (OSR), compiled inside a stream (perf53e).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void ReadDriver(Socket connection, RapidInbox inbox, CancellationToken token)
    {
        var buffer = new byte[4096];
        using CancellationTokenRegistration stop = token.Register(static s => ((Socket)s!).Dispose(), connection);
        try
        {
            while (true)
            {
                int n = connection.Receive(buffer, SocketFlags.None);
                if (n == 0)
                {
                    return;
                }
                string text = Encoding.Latin1.GetString(buffer, 0, n);
                CountStatements(connection, text);
                inbox.Add(text);
            }
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException or OperationCanceledException)
        {
            // Closed by the host, by a fault or by the controller stopping.
        }
        finally
        {
            inbox.Close();
        }
    }

    /// <summary>
    /// Counts each complete statement of <paramref name="text"/> received (a ';' outside a quoted text ends one). A statement that
    /// lies in one arrival is cut from it where it lies; one that began in an earlier arrival is joined in <see cref="_statement"/>.
    /// </summary>
    private void CountStatements(Socket connection, string text)
    {
        lock (Gate)
        {
            if (!ReferenceEquals(connection, _driverSocket))
            {
                return;
            }
            ReadOnlySpan<char> rest = text;
            while (true)
            {
                int at = _inText ? rest.IndexOf('"') : rest.IndexOfAny('"', ';');
                if (at < 0)
                {
                    _statement.Append(rest);
                    return;
                }
                if (rest[at] == '"')
                {
                    _inText = !_inText;
                    _statement.Append(rest[..(at + 1)]);
                    rest = rest[(at + 1)..];
                    continue;
                }
                ReadOnlySpan<char> part = rest[..at];
                rest = rest[(at + 1)..];
                string statement;
                if (_statement.Length == 0)
                {
                    ReadOnlySpan<char> trimmed = part.Trim();
                    if (trimmed.IsEmpty)
                    {
                        continue;
                    }
                    statement = string.Concat(trimmed, ";");
                }
                else
                {
                    string joined = _statement.Append(part).ToString().Trim();
                    _statement.Clear();
                    if (joined.Length == 0)
                    {
                        continue;
                    }
                    statement = joined + ";";
                }
                int id = IdOf(statement.AsSpan(0, statement.Length - 1));
                ReceiveOnCaller(id, statement, out int generation, keepsCut: true);
                _awaiting.Enqueue(new TwinRequest(id, generation));
            }
        }
    }

    bool IRapidSocketSeam.Send(Socket connection, Stream outbox, byte[] bytes, CancellationToken task)
    {
        TwinRequest? acknowledged = null;
        List<TwinRequest>? skipped = null;
        lock (Gate)
        {
            if (ReferenceEquals(connection, _driverSocket) && _awaiting.Count > 0 && AcknowledgedId(bytes) is int id && Awaits(id))
            {
                while (acknowledged is null)
                {
                    TwinRequest r = _awaiting.Dequeue();
                    if (r.Id == id)
                    {
                        acknowledged = r;
                    }
                    else
                    {
                        (skipped ??= []).Add(r); // read but refused by the driver's parser: never executed
                    }
                }
            }
        }
        if (skipped is not null)
        {
            foreach (TwinRequest r in skipped)
            {
                CompleteReceivedOnCaller(r, Math.Max(r.Id, 0), r.Generation, runs: false, task);
            }
        }
        if (acknowledged is null)
        {
            bool sent = SendDirect(outbox, bytes);
            if (sent && bytes.Length > 3 && bytes[0] == '$' && bytes[1] == '2' && bytes[2] == '4' && ReferenceEquals(connection, Volatile.Read(ref _monitorSocket)))
            {
                Interlocked.Increment(ref _monitorReportsSent); // the first of the monitor's three chunks of a state report
            }
            return sent;
        }
        acknowledged.Acknowledgement = bytes;
        // Only the driver task sends acknowledgements: the count moves when this one reached the host. A paused controller holds
        // the driver here, at its SocketSend.
        int before = AcknowledgementsSent;
        CompleteReceivedOnCaller(acknowledged, Math.Max(acknowledged.Id, 0), acknowledged.Generation, runs: true, task);
        return AcknowledgementsSent != before;
    }

    /// <summary>True when a request with <paramref name="id"/> was read and not yet acknowledged (called under the gate).</summary>
    private bool Awaits(int id)
    {
        foreach (TwinRequest r in _awaiting)
        {
            if (r.Id == id)
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>Sends the driver's acknowledgement of <paramref name="request"/> through the fault plan (none for a request it skipped).</summary>
    private void AcknowledgeTwin(TwinRequest request, CancellationToken token)
    {
        if (request.Acknowledgement is { Length: > 0 } bytes)
        {
            Acknowledge(bytes, Math.Max(request.Id, 0), token);
        }
    }

    /// <summary>Lets every request waiting for an acknowledgement go (the controller stops): counted executed, never acknowledged.</summary>
    private void ReleaseTwinRequests()
    {
        TwinRequest[] waiting;
        lock (Gate)
        {
            waiting = [.. _awaiting];
            _awaiting.Clear();
            _driverSocket = null;
        }
        foreach (TwinRequest r in waiting)
        {
            try
            {
                CompleteReceivedOnCaller(r, Math.Max(r.Id, 0), r.Generation, runs: false, new CancellationToken(canceled: true));
            }
            catch (OperationCanceledException)
            {
                // Paused when stopped: it stays unexecuted.
            }
        }
    }

    private static bool SendDirect(Stream outbox, byte[] bytes)
    {
        if (outbox is TwinHeldOutbox held)
        {
            return held.TryWrite(bytes); // closed: false, without the IOException
        }
        try
        {
            outbox.Write(bytes);
            return true;
        }
        catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
        {
            return false;
        }
    }

    /// <summary>
    /// The id after '@' at the start of a request, or 0 (the driver's parser reads a request without one as id 0). Up to nine
    /// digits are read as they are; anything else as a number (as before: a fraction or an exponent is taken, rounded down).
    /// </summary>
    private static int IdOf(ReadOnlySpan<char> statement)
    {
        if (statement[0] != '@')
        {
            return 0;
        }
        ReadOnlySpan<char> rest = statement[1..];
        int end = rest.IndexOfAny(" \t\r\n");
        ReadOnlySpan<char> digits = end < 0 ? rest : rest[..end];
        if (digits.Length is > 0 and <= 9 && !digits.ContainsAnyExceptInRange('0', '9'))
        {
            int value = 0;
            foreach (char c in digits)
            {
                value = value * 10 + (c - '0');
            }
            return value;
        }
        return double.TryParse(digits, NumberStyles.Float, CultureInfo.InvariantCulture, out double id) && id > 0 && id < int.MaxValue ? (int)id : 0;
    }

    /// <summary>The id an acknowledgement the driver writes is for (<c>@id code;</c>, or <c>code;</c> for id 0), or null for anything else.</summary>
    private static int? AcknowledgedId(byte[] bytes)
    {
        ReadOnlySpan<byte> text = bytes.AsSpan().Trim(" \t\r\n"u8);
        if (text.Length < 2 || text[^1] != (byte)';')
        {
            return null;
        }
        ReadOnlySpan<byte> body = text[..^1];
        if (body[0] == (byte)'@')
        {
            int space = body.IndexOf((byte)' ');
            return space > 1 && Digits(body[1..space]) is int id && Digits(body[(space + 1)..]) is not null ? id : null;
        }
        return Digits(body) is not null ? 0 : null;
    }

    /// <summary>The value of an optionally signed run of ASCII digits, or null when it is anything else (or too long for an int).</summary>
    private static int? Digits(ReadOnlySpan<byte> text)
    {
        int start = text.Length > 0 && (text[0] == (byte)'-' || text[0] == (byte)'+') ? 1 : 0;
        if (text.Length == start || text.Length - start > 10)
        {
            return null;
        }
        long value = 0;
        for (int i = start; i < text.Length; i++)
        {
            if (text[i] is < (byte)'0' or > (byte)'9')
            {
                return null;
            }
            value = value * 10 + (text[i] - '0');
        }
        return value > int.MaxValue ? null : (int)(text[0] == (byte)'-' ? -value : value);
    }

    /// <summary>
    /// The tool our driver holds in its PERS <c>cursorTool</c> (set by requests 8 and 9, used by its next move), or null when the
    /// loaded program has none: a controller's state shows the tool the program selected, before a move uses it.
    /// </summary>
    private static Pose? DriverTool(RapidTwinController twin)
    {
        if (twin.Persistents.TryGetValue("cursorTool", out RapidCell? cell) && cell.Value is RapidRecord { Fields: [_, RapidRecord frame, ..] })
        {
            try
            {
                return RapidGeometry.ToPose(frame, 0);
            }
            catch (Exception e) when (e is RapidRuntimeException or ArgumentException)
            {
                return null; // not a rotation (the driver's data as the host sent it): its next move refuses it
            }
        }
        return null;
    }

    /// <summary>The robot as the twin's arm has it now.</summary>
    private static VirtualAbbState TwinState(RapidTwinController twin, VirtualAbbState basis)
    {
        var seen = new TwinObservation();
        foreach ((string name, string type) in twin.Options.Signals)
        {
            if (twin.Signal(name) is { } s && type == "signaldo")
            {
                seen.Digital(name, twin.Io.GetBit(s.Bank, s.Index));
            }
            else if (twin.Signal(name) is { } a && type == "signalao")
            {
                seen.Analog(name, twin.Io.GetNumber(a.Bank, a.Index));
            }
        }
        return seen.Apply(basis, twin.Arm, twin.Arm.Joints, DriverTool(twin) ?? twin.Arm.ToolCenter);
    }
}
