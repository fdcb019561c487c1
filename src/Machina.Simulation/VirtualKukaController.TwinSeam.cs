using System.Globalization;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;

namespace Machina.Simulation;

/// <summary>
/// The virtual KUKA's faults and inspection, at the seams a KR C4 has: its EthernetKRL channels. A client that connects to the
/// driver channel becomes the driver connection (or is refused by the fault plan); each document the host sends is logged as
/// received, action by action; the driver's EKI_Send of an acknowledgement (<c>R</c>) goes through the controller's fault plan
/// (held, delayed, cut, lost, followed by a drop) and is counted as executed, the driver waiting there as on a slow network.
/// The monitor's reports (<c>P</c>) are counted.
/// </summary>
public sealed partial class VirtualKukaController : IEkiSeam
{
    private readonly Dictionary<int, TaskCompletionSource<TwinAck>> _acks = [];
    private CancellationToken _twinToken;
    private byte[]? _heldTwinAcknowledgement;

    /// <summary>An action the driver received: it enters the controller's buffer and is executed when the driver acknowledges it.</summary>
    private sealed record TwinAction(int Id, TaskCompletionSource<TwinAck> Acknowledged);

    /// <summary>
    /// An acknowledgement the driver is sending (its action ran, the fault plan decides what reaches the host), or with
    /// <paramref name="Failure"/> the text of the failure it sent instead.
    /// </summary>
    private sealed record TwinAck(int Id, byte[] Bytes, TaskCompletionSource<bool> Done, string? Failure = null)
    {
        /// <summary>True when the driver ran the action and never sent its acknowledgement (its state told the host instead).</summary>
        public bool Unsent { get; init; }

        /// <summary>True when the failure is Robot.Stop's (code 7): the driver ended the action part-way and keeps serving.</summary>
        public bool Stopped { get; init; }

        /// <summary>True for an action a restart that loses the progress lost before the driver ran it.</summary>
        public bool Lost { get; init; }
    }

    /// <summary>True while a client waits at the driver's port for the program to open its channel again (a held program greets it when it goes on).</summary>
    internal bool ClientWaiting
    {
        get
        {
            try
            {
                return _driverListener?.Pending() == true;
            }
            catch (Exception e) when (e is InvalidOperationException or ObjectDisposedException or SocketException)
            {
                return false;
            }
        }
    }

    /// <summary>True while the driver's EthernetKRL channel has a client (false once it saw a client leave).</summary>
    internal bool DriverChannelConnected => Twin?.EkiConnected(DriverChannel) == true;

    bool IEkiSeam.Accepted(EkiChannel channel, TcpClient client) =>
        !IsDriver(channel) || AttachClientAsync(client, (_, _) => Task.CompletedTask, _twinToken).GetAwaiter().GetResult();

    void IEkiSeam.Received(EkiChannel channel, IReadOnlyList<(string Tag, string Value)> values)
    {
        if (!IsDriver(channel))
        {
            return;
        }
        // Each action's values, from its ID to the next ID, as the element the host wrote.
        var actions = new List<(int Id, string Text)>();
        StringBuilder? action = null;
        int id = 0;
        foreach ((string tag, string value) in values)
        {
            if (tag == "DT/DR/A/@ID")
            {
                if (action is not null)
                {
                    actions.Add((id, action.Append("/>").ToString()));
                }
                action = new StringBuilder("<A");
                id = int.TryParse(value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int parsed) ? parsed : 0;
            }
            int at = tag.LastIndexOf('@');
            action?.Append(' ').Append(tag, at + 1, tag.Length - at - 1).Append("=\"").Append(Escape(value)).Append('"');
        }
        if (action is not null)
        {
            actions.Add((id, action.Append("/>").ToString()));
        }
        try
        {
            foreach ((int actionId, string text) in actions)
            {
                EnqueueAsync(new TwinAction(actionId, Acknowledgement(actionId)), actionId, text, _twinToken).AsTask().GetAwaiter().GetResult();
            }
        }
        catch (Exception e) when (e is OperationCanceledException or System.Threading.Channels.ChannelClosedException)
        {
            // Stopping.
        }
    }

    /// <summary>Where the acknowledgement of action <paramref name="id"/> meets its entry in the buffer.</summary>
    private TaskCompletionSource<TwinAck> Acknowledgement(int id)
    {
        lock (Gate)
        {
            // An entry of an action the buffer dropped is not shared with the same id sent again (the restart emptied the ring).
            if (!_acks.TryGetValue(id, out TaskCompletionSource<TwinAck>? ack) || TakeDropped(ack))
            {
                ack = new TaskCompletionSource<TwinAck>(TaskCreationOptions.RunContinuationsAsynchronously);
                _acks[id] = ack;
            }
            return ack;
        }
    }

    private static string Escape(string value) => value.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal)
        .Replace(">", "&gt;", StringComparison.Ordinal).Replace("\"", "&quot;", StringComparison.Ordinal);

    bool IEkiSeam.Send(EkiChannel channel, string root, string xml)
    {
        byte[] bytes = Encoding.UTF8.GetBytes(xml);
        if (!IsDriver(channel))
        {
            bool sent = channel.SendDirect(bytes);
            if (sent && root == "P")
            {
                Interlocked.Increment(ref _monitorReportsSent);
            }
            return sent;
        }
        try
        {
            if (root == "F")
            {
                FailureSent(xml);
            }
            else if (root == "S")
            {
                StateSent(xml);
            }
            if (root != "R")
            {
                return SendToClientAsync(bytes, _twinToken).GetAwaiter().GetResult();
            }
            TaskCompletionSource<TwinAck>? entry;
            bool dropped;
            int id = IdOf(xml);
            lock (Gate)
            {
                _acks.Remove(id, out entry);
                dropped = TakeDropped(entry);
            }
            if (entry is null)
            {
                // An action the controller's buffer never held: sent as it is.
                return SendToClientAsync(bytes, _twinToken).GetAwaiter().GetResult();
            }
            if (dropped)
            {
                // It ran, but a restart under way dropped it from the buffer: logged here, acknowledged to nobody.
                RanOutsideBuffer(id);
                return false;
            }
            var done = new TaskCompletionSource<bool>(TaskCreationOptions.RunContinuationsAsynchronously);
            entry.TrySetResult(new TwinAck(id, bytes, done));
            return done.Task.WaitAsync(_twinToken).GetAwaiter().GetResult();
        }
        catch (Exception e) when (e is OperationCanceledException or System.Threading.Channels.ChannelClosedException)
        {
            throw new OperationCanceledException("the controller stops", e, _twinToken);
        }
    }

    /// <summary>
    /// The buffer reached an action: it counts as executed when the driver acknowledges it (the execution loop waits for that);
    /// a refusal with the driver's text when the driver sent a failure instead.
    /// </summary>
    private static TwinAck AwaitTwinAction(TwinAction action, CancellationToken token)
    {
        TwinAck ack = action.Acknowledged.Task.WaitAsync(token).GetAwaiter().GetResult()!;
        return ack.Failure is { } failure ? throw new VirtualRefusalException(failure) : ack;
    }

    void IEkiSeam.Closed(EkiChannel channel, TcpClient client)
    {
        if (IsDriver(channel))
        {
            DropClient(client);
        }
    }

    private static bool IsDriver(EkiChannel channel) => string.Equals(channel.Name, DriverChannel, StringComparison.OrdinalIgnoreCase);

    /// <summary>The ID attribute of an element the driver sends (0 when it has none).</summary>
    private static int IdOf(string xml) => IntegerOf(xml, " ID=\"");

    /// <summary>The integer after <paramref name="attribute"/> (name, equals sign and opening quote) in <paramref name="xml"/>, or 0.</summary>
    private static int IntegerOf(string xml, string attribute)
    {
        int start = xml.IndexOf(attribute, StringComparison.Ordinal);
        if (start < 0)
        {
            return 0;
        }
        start += attribute.Length;
        int end = xml.IndexOf('"', start);
        return int.TryParse(xml.AsSpan(start, end - start), NumberStyles.Integer, CultureInfo.InvariantCulture, out int id) ? id : 0;
    }

    /// <summary>
    /// The driver greets a connection with its progress: the actions it ran up to Executed whose acknowledgement it did not send
    /// (no greeted connection then) are executed for the buffer too, with nothing sent; a held acknowledgement is now history.
    /// The state leaves only once the controller's execution log holds them: a host that reads the log as soon as the state
    /// arrived finds there what the state says (under load the buffer's loop logged them after the host had looked).
    /// </summary>
    private void StateSent(string xml) => CompleteRanUpTo(IntegerOf(xml, " Executed=\""));

    /// <summary>
    /// Executes for the buffer, with nothing sent, the actions up to <paramref name="executed"/> (the driver's progress) whose
    /// acknowledgement the driver did not send, and waits until the execution log holds them.
    /// </summary>
    private void CompleteRanUpTo(int executed)
    {
        List<(int Id, TaskCompletionSource<TwinAck> Entry)> ran;
        List<int> dropped = [];
        lock (Gate)
        {
            _heldTwinAcknowledgement = null;
            ran = [.. _acks.Where(a => a.Key <= executed).OrderBy(a => a.Key).Select(a => (a.Key, a.Value))];
            foreach ((int id, TaskCompletionSource<TwinAck> entry) in ran)
            {
                _acks.Remove(id);
                if (TakeDropped(entry))
                {
                    dropped.Add(id);
                }
            }
        }
        var logged = new List<Task<bool>>(ran.Count);
        foreach ((int id, TaskCompletionSource<TwinAck> entry) in ran)
        {
            var done = new TaskCompletionSource<bool>(TaskCreationOptions.RunContinuationsAsynchronously);
            if (!dropped.Contains(id) && entry.TrySetResult(new TwinAck(id, [], done) { Unsent = true }))
            {
                logged.Add(done.Task);
            }
        }
        // The buffer's loop sets Done after it logged the action as executed (before its acknowledgement step, which sends nothing).
        Task.WhenAll(logged).WaitAsync(_twinToken).GetAwaiter().GetResult();
        // Those a restart dropped from the buffer come after the one its loop held: nobody else logs them (waiting for the loop
        // to do it was the hang of the restart that loses the progress).
        foreach (int id in dropped)
        {
            RanOutsideBuffer(id);
        }
    }

    /// <summary>The Text attribute of a failure the driver sends, unescaped.</summary>
    private static string TextOf(string xml)
    {
        int start = xml.IndexOf("Text=\"", StringComparison.Ordinal);
        if (start < 0)
        {
            return xml;
        }
        start += 6;
        int end = xml.IndexOf('"', start);
        return System.Net.WebUtility.HtmlDecode(xml[start..end]);
    }

    /// <summary>The driver reports a failure: an acknowledgement held back goes first, and the failure is kept as an error.</summary>
    private void FailureSent(string xml)
    {
        TaskCompletionSource<TwinAck>? entry;
        bool stopped = IntegerOf(xml, " Code=\"") == StoppedCode;
        List<TaskCompletionSource<TwinAck>> dropped = [];
        lock (Gate)
        {
            _acks.Remove(IdOf(xml), out entry);
            if (stopped)
            {
                // The driver dropped every other action it held: none of them will be acknowledged.
                dropped.AddRange(_acks.Values);
                _acks.Clear();
            }
        }
        if (stopped)
        {
            DropBuffer("stopped by the host (Robot.Stop)");
        }
        entry?.TrySetResult(new TwinAck(IdOf(xml), [], new TaskCompletionSource<bool>(), TextOf(xml)) { Stopped = stopped });
        foreach (TaskCompletionSource<TwinAck> waiting in dropped)
        {
            waiting.TrySetCanceled();
        }
        byte[]? held;
        lock (Gate)
        {
            held = _heldTwinAcknowledgement;
            _heldTwinAcknowledgement = null;
        }
        if (held is not null)
        {
            SendToClientAsync(held, _twinToken).GetAwaiter().GetResult();
        }
    }

    /// <summary>Sends an acknowledgement of the twin's driver as the options write it, through the fault plan.</summary>
    private async Task<bool> AcknowledgeTwinAsync(TwinAck ack, CancellationToken token)
    {
        try
        {
            if (ack.Unsent)
            {
                return true;
            }
            switch (_options.AcknowledgementWrites)
            {
                case AcknowledgementWrites.Split:
                    // The first part records the action as executed; the rest completes the element.
                    await SendToClientAsync(ack.Bytes.AsMemory(0, 4), token, executedId: ack.Id).ConfigureAwait(false);
                    await AcknowledgeTwinPartAsync(ack.Bytes.AsMemory(4), ack.Id, token).ConfigureAwait(false);
                    break;
                case AcknowledgementWrites.Joined when _heldTwinAcknowledgement is null && TwinRingCount() > 0:
                    // Held until the driver acknowledges the next action, which it runs now.
                    lock (Gate)
                    {
                        _heldTwinAcknowledgement = ack.Bytes;
                    }
                    break;
                case AcknowledgementWrites.Joined when _heldTwinAcknowledgement is not null:
                    byte[] held;
                    lock (Gate)
                    {
                        held = _heldTwinAcknowledgement!;
                        _heldTwinAcknowledgement = null;
                    }
                    await AcknowledgeTwinPartAsync(held.Concat(ack.Bytes).ToArray(), ack.Id, token).ConfigureAwait(false);
                    break;
                default:
                    await AcknowledgeTwinPartAsync(ack.Bytes, ack.Id, token).ConfigureAwait(false);
                    break;
            }
            ack.Done.TrySetResult(true);
        }
        finally
        {
            ack.Done.TrySetResult(false);
        }
        return true;
    }

    /// <summary>Sends an acknowledgement through the fault plan (a restart that loses the buffer resets the driver program first, see <see cref="RestartingLosingBuffer"/>).</summary>
    private Task AcknowledgeTwinPartAsync(ReadOnlyMemory<byte> bytes, int id, CancellationToken token) => AcknowledgeAsync(bytes, id, token);

    /// <summary>
    /// The fault plan's RestartLosingBuffer is a program reset: the driver program stops (it waits in the EKI_Send of the
    /// acknowledgement just sent, and stops before its next statement) before the client is dropped, so a host that
    /// reconnects at once meets the program that starts again from its first line, never the one that was reset.
    /// </summary>
    private protected override void RestartingLosingBuffer()
    {
        if (Twin is not null)
        {
            ResetDriverProgram();
        }
    }

    /// <summary>
    /// The fault plan's RestartLosingProgress: a program reset as above, after which the driver starts with the data list as
    /// loaded (its progress <c>last_executed</c>, <c>last_received</c> at 0), as after a cold start that reloads the program.
    /// </summary>
    private protected override void RestartingLosingProgress()
    {
        if (Twin is not null)
        {
            lock (Gate)
            {
                _forgetProgress = true;
                _driverRun?.Cancel(); // the buffer learns what ran once the driver stopped (RunDriver)
                _heldTwinAcknowledgement = null;
            }
        }
    }

    /// <summary>An action a restart lost before the driver ran it: the execution loop that waited for it goes on without it.</summary>
    private protected override bool LostInRestart(object request) =>
        request is TwinAction { Acknowledged.Task: { IsCompletedSuccessfully: true, Result.Lost: true } };

    /// <summary>
    /// After a restart that loses the progress, once the driver stopped: what it ran up to <paramref name="executed"/> with
    /// nobody connected is executed for the buffer (and logged), every other action it had received is lost.
    /// </summary>
    private void SettleRestart(int executed)
    {
        CompleteRanUpTo(executed);
        List<(int Id, TaskCompletionSource<TwinAck> Entry)> lost;
        lock (Gate)
        {
            lost = [.. _acks.Select(a => (a.Key, a.Value))];
            _acks.Clear();
            _dropped.Clear();
        }
        foreach ((int id, TaskCompletionSource<TwinAck> entry) in lost)
        {
            entry.TrySetResult(new TwinAck(id, [], new TaskCompletionSource<bool>()) { Lost = true });
        }
    }

    /// <summary>How many actions the driver's ring holds (its slot_count), or 0 without a twin.</summary>
    private int TwinRingCount() => Twin is { } twin && twin.Modules.TryGetValue("machina_kuka_driver", out KrlModule? module)
        ? KrlValues.ToInt(module.Data["slot_count"].Value)
        : 0;
}
