namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>The failure code of the driver's stop (Robot.Stop): the action under way ended part-way, the driver keeps serving.</summary>
    private const int StoppedCode = 7;

    /// <summary>The driver's answer to a stop (<c>&lt;C K="3"/&gt;</c>), sent after it emptied its ring, with or without a failure first.</summary>
    private const int StoppedAnswer = 3;

    /// <summary>True from a stop's failure (code 7), which dropped what the driver held, to the stop's answer. Guarded by the gate.</summary>
    private bool _stopDropped;

    /// <summary>
    /// The driver reports a failure (<c>&lt;F ID Code Text&gt;</c>) instead of the acknowledgement: the action is refused with
    /// the driver's text (kept as an error, counted executed, not logged: a target no axis position reaches, an axis beyond its
    /// software limit switch, a speed of 0, an output that does not exist), and the driver halts, so nothing after it runs; the
    /// EthernetKRL channel stays open. A stop (code 7) is not a halt: the driver dropped every other action it held (none of
    /// them runs or is acknowledged) and serves the next connection. An acknowledgement held back goes out first.
    /// </summary>
    private void FailureSent(string xml)
    {
        bool stopped = IntegerOf(xml, " Code=\"") == StoppedCode;
        TwinAction? action;
        lock (Gate)
        {
            action = TakeHeld(IdOf(xml));
        }
        if (stopped)
        {
            DropHeld();
            lock (Gate)
            {
                _stopDropped = true;
            }
        }
        if (action is { Dropped: false })
        {
            RefuseOnCaller(TextOf(xml));
        }
        byte[]? held;
        lock (Gate)
        {
            held = _heldTwinAcknowledgement;
            _heldTwinAcknowledgement = null;
        }
        if (held is not null)
        {
            SendToClient(held);
        }
    }

    /// <summary>
    /// The driver answered a stop (<c>&lt;C K="3"/&gt;</c>): it emptied its ring. With no action running it sent no failure
    /// first, so what it held is dropped here (counted lost, none of it runs or is acknowledged); after a failure it was already.
    /// </summary>
    private void StopAnswered()
    {
        bool dropped;
        lock (Gate)
        {
            dropped = _stopDropped;
            _stopDropped = false;
        }
        if (!dropped)
        {
            DropHeld();
        }
    }

    /// <summary>Drops every action the driver holds, as its stop does: counted lost (<see cref="DiscardHeld"/>), then forgotten.</summary>
    private void DropHeld()
    {
        DropBuffer("stopped by the host (Robot.Stop)");
        lock (Gate)
        {
            _held.Clear();
        }
    }
}
