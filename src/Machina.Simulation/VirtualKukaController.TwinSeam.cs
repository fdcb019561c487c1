using System.Globalization;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

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
    /// <summary>
    /// The actions the driver channel received and the driver has not settled yet (acknowledged, reported failed, or run while
    /// nobody listened), in the order received: what its ring and the channel's memory hold. Those a restart dropped come
    /// first (<see cref="DiscardHeld"/>). Guarded by the gate.
    /// </summary>
    private readonly List<TwinAction> _held = [];
    private CancellationToken _twinToken;
    private readonly ConnectionLog _connections;
    private byte[]? _heldTwinAcknowledgement;

    /// <summary>The writer of the received actions' log text, made when the log is first read; used under the gate.</summary>
    private EkiReceivedText? _receivedText;

    /// <summary>The tags of the last action the driver channel received, which the next action with the same tags shares in the log.</summary>
    private string[]? _receivedTags;

    /// <summary>
    /// An action the driver channel received, held until the driver settles it: a value in the held list (one object an action
    /// less on the EKI reader); <paramref name="Dropped"/> is true once a restart dropped it (counted lost): if the driver runs it
    /// anyway, it is logged executed then.
    /// </summary>
    private readonly record struct TwinAction(int Id, bool Dropped = false);

    /// <summary>An acknowledgement the driver is sending: its action ran, the fault plan decides what reaches the host.</summary>
    private sealed class TwinAck(int id, byte[] bytes, bool unsent = false)
    {
        public int Id { get; } = id;

        public byte[] Bytes { get; } = bytes;

        /// <summary>True when the driver ran the action and never sent its acknowledgement (its state told the host instead).</summary>
        public bool Unsent { get; } = unsent;

        /// <summary>True once it went through the fault plan (whatever of it reached the host).</summary>
        public bool Done { get; set; }
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

    bool IEkiSeam.Accepted(EkiChannel channel, TcpClient client)
    {
        _connections.Connected(IsDriver(channel) ? "driver" : "monitor", client, client.Client);
        bool kept = !IsDriver(channel) || AttachClient(client, DriverWire(client));
        if (!kept)
        {
            _connections.Left(client);
        }
        return kept;
    }

    /// <summary>
    /// The driver connection's writes go through the EthernetKRL stack's outbox, held until the robot interpreter waits (as RAPID's
    /// SocketSend); null (written at once) while the options shape the acknowledgement writes themselves (their tests want those segments).
    /// </summary>
    private TwinHeldOutbox? DriverWire(TcpClient client) =>
        _options.AcknowledgementWrites == AcknowledgementWrites.Whole && Twin is { } twin ? new TwinHeldOutbox(client.Client, twin.Sends) : null;

    void IEkiSeam.Received(EkiChannel channel, ReadOnlySpan<(string Tag, string Value)> values)
    {
        if (!IsDriver(channel))
        {
            return;
        }
        // Each action's values, from its ID to the next ID: the log writes them as the element the host wrote when it is read.
        int start = NextId(values, 0);
        while (start < values.Length)
        {
            int end = NextId(values, start + 1);
            int id = int.TryParse(values[start].Value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int parsed) ? parsed : 0;
            HoldReceived(id, EkiReceivedAction.Of(values[start..end], ref _receivedTags));
            start = end;
        }
    }

    /// <summary>A received action's log text, written the first time the log is read (under the gate, once: the log keeps it).</summary>
    private protected override string RequestText(object entry) =>
        entry is EkiReceivedAction action ? action.Text(_receivedText ??= new EkiReceivedText()) : base.RequestText(entry);

    /// <summary>Where the next action's ID is in <paramref name="values"/> from <paramref name="from"/> on (their length when none).</summary>
    private static int NextId(ReadOnlySpan<(string Tag, string Value)> values, int from)
    {
        for (int i = from; i < values.Length; i++)
        {
            if (values[i].Tag == "DT/DR/A/@ID")
            {
                return i;
            }
        }
        return values.Length;
    }

    /// <summary>Counts action <paramref name="id"/> received and holds it until the driver settles it (not when a restart cut its client off).</summary>
    private void HoldReceived(int id, EkiReceivedAction action)
    {
        lock (Gate)
        {
            if (!ReceiveOnCaller(id, action, out _))
            {
                return;
            }
            if (_held.Count > 0 && _held[0].Dropped)
            {
                // One a restart dropped is not the one sent again with its id (the restart emptied the ring).
                _held.RemoveAll(a => a.Dropped && a.Id == id);
            }
            _held.Add(new TwinAction(id));
        }
    }

    /// <summary>Takes the held action <paramref name="id"/> (the first with that id), or null; call it under the gate.</summary>
    private TwinAction? TakeHeld(int id)
    {
        for (int i = 0; i < _held.Count; i++)
        {
            if (_held[i].Id == id)
            {
                TwinAction action = _held[i];
                _held.RemoveAt(i);
                return action;
            }
        }
        return null;
    }

    bool IEkiSeam.Send(EkiChannel channel, string root, byte[] bytes)
    {
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
            switch (root)
            {
                case "R":
                    return Acknowledged(IdOf(bytes), bytes); // once an action: the id read from the bytes, no text made
                case "F":
                    FailureSent(Encoding.UTF8.GetString(bytes));
                    break;
                case "S":
                    StateSent(Encoding.UTF8.GetString(bytes));
                    break;
                case "C" when IntegerOf(Encoding.UTF8.GetString(bytes), " K=\"") == StoppedAnswer:
                    StopAnswered();
                    break;
            }
            return SendToClient(bytes);
        }
        catch (OperationCanceledException e)
        {
            throw new OperationCanceledException("the controller stops", e, _twinToken);
        }
    }

    /// <summary>
    /// The driver's EKI_Send of <c>R</c>: its arm ran action <paramref name="id"/>. Settled here, on the driver's thread: logged
    /// executed and acknowledged through the fault plan (a held or delayed acknowledgement holds the driver, as a slow network
    /// would). True when it went through.
    /// </summary>
    private bool Acknowledged(int id, byte[] bytes)
    {
        TwinAction? action;
        lock (Gate)
        {
            action = TakeHeld(id);
        }
        if (action is not { } held)
        {
            return SendToClient(bytes); // an action the controller never held: sent as it is
        }
        if (held.Dropped)
        {
            // It ran, but a restart under way dropped it: logged here, acknowledged to nobody.
            RanOutsideBuffer(id);
            return false;
        }
        var ack = new TwinAck(id, bytes);
        CompleteReceivedOnCaller(ack, id, SettledByBrand, runs: true, _twinToken);
        return ack.Done;
    }

    void IEkiSeam.Closed(EkiChannel channel, TcpClient client)
    {
        _connections.Left(client);
        if (IsDriver(channel))
        {
            DropClient(client);
        }
    }

    private static bool IsDriver(EkiChannel channel) => string.Equals(channel.Name, DriverChannel, StringComparison.OrdinalIgnoreCase);

    /// <summary>The ID attribute of an element the driver sends (0 when it has none).</summary>
    private static int IdOf(string xml) => IntegerOf(xml, " ID=\"");

    /// <summary>The ID attribute of an element the driver sends, read from its UTF-8 bytes (0 when it has none): <see cref="IdOf(string)"/> without the text.</summary>
    private static int IdOf(ReadOnlySpan<byte> xml)
    {
        ReadOnlySpan<byte> attribute = " ID=\""u8;
        int start = xml.IndexOf(attribute);
        if (start < 0)
        {
            return 0;
        }
        start += attribute.Length;
        int end = xml[start..].IndexOf((byte)'"');
        return end >= 0 && int.TryParse(xml.Slice(start, end), NumberStyles.Integer, CultureInfo.InvariantCulture, out int id) ? id : 0;
    }

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
    /// They are settled on the driver's thread before the state leaves: a host that reads the log as soon as the state arrived
    /// finds there what the state says.
    /// </summary>
    private void StateSent(string xml) => CompleteRanUpTo(IntegerOf(xml, " Executed=\""));

    /// <summary>
    /// Settles, with nothing sent, the held actions up to <paramref name="executed"/> (the driver's progress) whose
    /// acknowledgement the driver did not send: they are in the execution log before this returns. Those a restart dropped
    /// are logged as run outside the buffer.
    /// </summary>
    private void CompleteRanUpTo(int executed)
    {
        List<TwinAction> ran = [];
        lock (Gate)
        {
            _heldTwinAcknowledgement = null;
            for (int i = 0; i < _held.Count;)
            {
                if (_held[i].Id <= executed)
                {
                    ran.Add(_held[i]);
                    _held.RemoveAt(i);
                }
                else
                {
                    i++;
                }
            }
        }
        foreach (TwinAction action in ran.Where(a => !a.Dropped))
        {
            CompleteReceivedOnCaller(new TwinAck(action.Id, [], unsent: true), action.Id, SettledByBrand, runs: true, _twinToken);
        }
        foreach (TwinAction action in ran.Where(a => a.Dropped))
        {
            RanOutsideBuffer(action.Id);
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

    /// <summary>Sends an acknowledgement of the twin's driver as the options write it, through the fault plan.</summary>
    private void AcknowledgeTwin(TwinAck ack, CancellationToken token)
    {
        if (ack.Unsent)
        {
            return;
        }
        switch (_options.AcknowledgementWrites)
        {
            case AcknowledgementWrites.Split:
                // The first part records the action as executed; the rest completes the element.
                SendToClient(ack.Bytes.AsSpan(0, 4), executedId: ack.Id);
                Acknowledge(ack.Bytes.AsSpan(4), ack.Id, token);
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
                Acknowledge([.. held, .. ack.Bytes], ack.Id, token);
                break;
            default:
                Acknowledge(ack.Bytes, ack.Id, token);
                break;
        }
        ack.Done = true;
    }

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

    /// <summary>
    /// After a restart that loses the progress, once the driver stopped: what it ran up to <paramref name="executed"/> with
    /// nobody connected is executed for the buffer (and logged), every other action it had received is lost.
    /// </summary>
    private void SettleRestart(int executed)
    {
        CompleteRanUpTo(executed);
        List<TwinAction> lost;
        lock (Gate)
        {
            lost = [.. _held];
            _held.Clear();
        }
        foreach (TwinAction action in lost.Where(a => !a.Dropped))
        {
            LostOnCaller(); // those the restart dropped were counted lost then
        }
    }

    /// <summary>How many actions the driver's ring holds (its slot_count), or 0 without a twin.</summary>
    private int TwinRingCount() => Twin is { } twin && twin.Modules.TryGetValue("machina_kuka_driver", out KrlModule? module)
        ? KrlValues.ToInt(module.Data["slot_count"].Value)
        : 0;
}
