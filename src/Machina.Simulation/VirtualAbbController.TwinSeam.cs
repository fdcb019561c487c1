using System.Globalization;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Simulation;

/// <summary>
/// The virtual ABB's faults and inspection when it runs RAPID, at the seams a real controller has: the driver task's socket.
/// The connection its SocketAccept takes becomes the driver connection (refused by the fault plan as a busy network would);
/// each statement its SocketReceive reads is a request received (counted, logged, buffered); its SocketSend of an
/// acknowledgement (<c>@id code;</c>, or <c>code;</c> for id 0) is what its arm just executed: that write goes through the
/// fault plan (held, delayed, cut, lost, followed by a drop) and is counted as executed. Everything else it sends (handshake,
/// information, failure reports) and the monitor task's sockets go straight to the wire.
/// </summary>
public sealed partial class VirtualAbbController : IRapidSocketSeam
{
    private readonly Queue<TwinRequest> _awaiting = new();
    private readonly StringBuilder _statement = new();
    private bool _inText;
    private Socket? _driverSocket;
    private Socket? _monitorSocket;

    /// <summary>A request the driver task read; its acknowledgement (null: the driver never sent one) and whether it reached the host.</summary>
    private sealed class TwinRequest(int id, Socket connection)
    {
        public int Id { get; } = id;

        public Socket Connection { get; } = connection;

        public TaskCompletionSource<byte[]?> Acked { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public TaskCompletionSource<bool> Done { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void Skip()
        {
            Acked.TrySetResult(null);
            Done.TrySetResult(false);
        }
    }

    bool IRapidSocketSeam.Accepted(int localPort, Socket connection, CancellationToken task)
    {
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
        TwinRequest[] orphans;
        lock (Gate)
        {
            _driverSocket = connection;
            _statement.Clear();
            _inText = false;
            orphans = [.. _awaiting];
            _awaiting.Clear();
        }
        // The driver accepts again only once it ran everything it read (its ReadRequests found the link closed): what the last client
        // sent and was not acknowledged ran while nobody listened. It counts as executed, without an acknowledgement.
        foreach (TwinRequest orphan in orphans)
        {
            orphan.Acked.TrySetResult([]);
            orphan.Done.TrySetResult(false);
        }
        var client = new TcpClient();
        client.Client.Dispose();
        client.Client = connection;
        return AttachClientAsync(client, (_, _) => Task.CompletedTask, task).GetAwaiter().GetResult();
    }

    void IRapidSocketSeam.Received(Socket connection, string text, CancellationToken task)
    {
        var read = new List<(TwinRequest Request, string Text)>();
        lock (Gate)
        {
            if (!ReferenceEquals(connection, _driverSocket))
            {
                return;
            }
            foreach (char c in text)
            {
                if (c == '"')
                {
                    _inText = !_inText;
                }
                if (c != ';' || _inText)
                {
                    _statement.Append(c);
                    continue;
                }
                string statement = _statement.ToString().Trim();
                _statement.Clear();
                if (statement.Length > 0)
                {
                    var request = new TwinRequest(IdOf(statement), connection);
                    _awaiting.Enqueue(request);
                    read.Add((request, statement + ";"));
                }
            }
        }
        foreach ((TwinRequest request, string statement) in read)
        {
            EnqueueAsync(request, request.Id, statement, task).AsTask().GetAwaiter().GetResult();
        }
    }

    bool IRapidSocketSeam.Send(Socket connection, byte[] bytes, CancellationToken task)
    {
        TwinRequest? acknowledged = null;
        var skipped = new List<TwinRequest>();
        lock (Gate)
        {
            if (ReferenceEquals(connection, _driverSocket) && AcknowledgedId(bytes) is int id && _awaiting.Any(r => r.Id == id))
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
                        skipped.Add(r); // read but refused by the driver's parser: never executed
                    }
                }
            }
        }
        foreach (TwinRequest r in skipped)
        {
            r.Skip();
        }
        if (acknowledged is null)
        {
            bool sent = SendDirect(connection, bytes);
            if (sent && bytes.Length > 3 && bytes[0] == '$' && bytes[1] == '2' && bytes[2] == '4' && ReferenceEquals(connection, Volatile.Read(ref _monitorSocket)))
            {
                Interlocked.Increment(ref _monitorReportsSent); // the first of the monitor's three chunks of a state report
            }
            return sent;
        }
        acknowledged.Acked.TrySetResult(bytes);
        // The execution loop sends it through the fault plan; a paused controller holds the driver here, at its SocketSend.
        while (!acknowledged.Done.Task.Wait(TimeSpan.FromMilliseconds(100), task))
        {
            if (!StillConnected(connection))
            {
                return false;
            }
        }
        return acknowledged.Done.Task.Result;
    }

    /// <summary>Executes a request of the twin: waits until the driver acknowledged it (true when it never will: not executed).</summary>
    private static bool NeverAcknowledged(TwinRequest request) => request.Acked.Task.GetAwaiter().GetResult() is null;

    /// <summary>Sends the driver's acknowledgement through the fault plan and lets the driver go on.</summary>
    private async Task<bool> AcknowledgeTwinAsync(TwinRequest request, CancellationToken token)
    {
        try
        {
            if (await request.Acked.Task.ConfigureAwait(false) is { Length: > 0 } bytes)
            {
                // Only this loop sends acknowledgements: the count moves when this one reached the host.
                int sent = AcknowledgementsSent;
                await AcknowledgeAsync(bytes, Math.Max(request.Id, 0), token).ConfigureAwait(false);
                request.Done.TrySetResult(AcknowledgementsSent != sent);
            }
        }
        finally
        {
            request.Done.TrySetResult(false);
        }
        return true;
    }

    /// <summary>Lets every request waiting for an acknowledgement go (the controller stops).</summary>
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
            r.Skip();
        }
    }

    private bool StillConnected(Socket connection)
    {
        lock (Gate)
        {
            if (!ReferenceEquals(connection, _driverSocket))
            {
                return false;
            }
        }
        return HasClient;
    }

    private static bool SendDirect(Socket connection, byte[] bytes)
    {
        try
        {
            connection.Send(bytes);
            return true;
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            return false;
        }
    }

    /// <summary>The id after '@' at the start of a request, or 0 (the driver's parser reads a request without one as id 0).</summary>
    private static int IdOf(string statement)
    {
        if (statement[0] != '@')
        {
            return 0;
        }
        int end = statement.IndexOfAny([' ', '\t', '\r', '\n'], 1);
        string digits = end < 0 ? statement[1..] : statement[1..end];
        return double.TryParse(digits, NumberStyles.Float, CultureInfo.InvariantCulture, out double id) && id > 0 && id < int.MaxValue ? (int)id : 0;
    }

    /// <summary>The id an acknowledgement the driver writes is for (<c>@id code;</c>, or <c>code;</c> for id 0), or null for anything else.</summary>
    private static int? AcknowledgedId(byte[] bytes)
    {
        string text = Encoding.Latin1.GetString(bytes).Trim();
        if (text.Length < 2 || text[^1] != ';')
        {
            return null;
        }
        string body = text[..^1];
        if (body[0] == '@')
        {
            string[] parts = body[1..].Split(' ');
            return parts.Length == 2 && int.TryParse(parts[0], NumberStyles.Integer, CultureInfo.InvariantCulture, out int id) ? id : null;
        }
        return int.TryParse(body, NumberStyles.Integer, CultureInfo.InvariantCulture, out _) ? 0 : null;
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
        var digital = new Dictionary<string, bool>();
        var analog = new Dictionary<string, double>();
        foreach ((string name, string type) in twin.Options.Signals)
        {
            if (twin.Signal(name) is { } s && type == "signaldo" && twin.Io.GetBit(s.Bank, s.Index))
            {
                digital[name] = true;
            }
            else if (twin.Signal(name) is { } a && type == "signalao" && twin.Io.GetNumber(a.Bank, a.Index) is var v && v != 0)
            {
                analog[name] = v;
            }
        }
        Joints joints = twin.Arm.Joints;
        Pose tool = DriverTool(twin) ?? twin.Arm.ToolCenter;
        Pose tcp = twin.Arm.Model.Kinematics.Forward(joints) * tool;
        return basis with
        {
            Position = tcp.Position,
            Rotation = tcp.Rotation,
            Joints = joints,
            Tool = tool.Position == Vector.Zero && tool.Rotation.IsSimilar(Rotation.Identity, 1e-9) ? null : tool,
            DigitalOutputs = digital,
            AnalogOutputs = analog,
        };
    }
}
