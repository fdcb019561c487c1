namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>The connection being set up (its handshake is under way), or null.</summary>
    private Connection? _connecting;

    /// <summary>
    /// Reports of <see cref="_connecting"/> that arrived before it became current, in order: handled once it is. Of the live
    /// poses only the latest is kept (<c>IsMotion</c>): the robot is where the last one says.
    /// </summary>
    private List<(Action Handle, bool IsMotion)> _held = [];

    /// <summary>
    /// One connection: posts a driver's reports to the session's loop as messages. There, a report of the current link is
    /// handled; a report of the link being connected is held and handled, in order, once the link is current (see
    /// <see cref="Report"/>); any other is a report of a replaced link and is ignored.
    /// </summary>
    private sealed class Connection(OnlineSession session, IDeviceDriver driver) : IDeviceListener
    {
        internal IDeviceDriver Driver { get; } = driver;

        // Before the link is current the driver cannot map a controller's id to an action yet: it is mapped once it is.
        public void OnAcknowledged(int id) => OnAcknowledged(id, null);

        public void OnAcknowledged(int id, double value) => OnAcknowledged(id, (double?)value);

        private void OnAcknowledged(int id, double? value) =>
            session.Report(this, () => session.OnAcknowledged(this, id, value), () => session.OnAcknowledged(this, session.ActionIdOf(this, id), value));

        public void OnMotion(in MotionSample sample)
        {
            MotionSample copy = sample;
            session.Report(this, () => session.OnMotion(this, copy), isMotion: true);
        }

        public void OnStopped(MachinaException reason) => session.Report(this, () => session.OnStopped(this, reason));

        public void OnResumed() => session.Report(this, () => session.OnResumed(this));

        public void OnFailed(int id, string reason, string? code) => session.Report(this, () => session.OnFailed(this, id, reason, code));

        public void OnFault(MachinaException error) => session.Report(this, () => session.Fault(this, error));
    }

    /// <summary>
    /// Posts a driver's report: on the loop it is handled when <paramref name="link"/> is current, held (as
    /// <paramref name="whenHeld"/> if given; a live pose, <paramref name="isMotion"/>, replaces the one held before) while
    /// <paramref name="link"/> is being connected, and ignored otherwise. Returns once it is handled, as a call into the
    /// session did before the loop (a driver's loops hold no lock of theirs when they report); a report made from inside
    /// the loop (a driver answering in <c>Send</c>) is handled right after the message under way.
    /// </summary>
    private void Report(Connection link, Action handle, Action? whenHeld = null, bool isMotion = false)
    {
        Action message = () => Receive(link, handle, whenHeld, isMotion);
        if (IsOnLoop)
        {
            Post(message);
            return;
        }
        Ask(() =>
        {
            message();
            return true;
        });
    }

    private void Receive(Connection link, Action handle, Action? whenHeld, bool isMotion)
    {
        if (ReferenceEquals(_link, link))
        {
            handle();
        }
        else if (ReferenceEquals(_connecting, link))
        {
            if (isMotion)
            {
                _held.RemoveAll(static h => h.IsMotion);
            }
            _held.Add((whenHeld ?? handle, isMotion));
        }
    }

    /// <summary>The action id a controller's id stands for among the actions in flight (held acknowledgements), else the id itself.</summary>
    private int ActionIdOf(Connection link, int controllerId)
    {
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked && link.Driver.WireId(f.Action.Id) == controllerId)
            {
                return f.Action.Id;
            }
        }
        return controllerId;
    }
}
