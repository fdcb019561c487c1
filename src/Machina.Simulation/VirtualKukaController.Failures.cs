namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>The failure code of the driver's stop (Robot.Stop): the action under way ended part-way, the driver keeps serving.</summary>
    private const int StoppedCode = 7;

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
            DropBuffer("stopped by the host (Robot.Stop)"); // counts what it held as lost (DiscardHeld)
            lock (Gate)
            {
                _held.Clear();
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
}
