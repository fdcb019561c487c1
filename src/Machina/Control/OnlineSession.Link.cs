using System.Collections.Concurrent;

namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>
    /// The connection being set up (its handshake is under way), or null: claimed by <see cref="ConnectAsync"/> on the caller's
    /// thread (compare-and-swap, so one at a time), cleared on the loop when it attaches or is refused, or by the caller when its
    /// handshake fails.
    /// </summary>
    private Connection? _connecting;

    /// <summary>
    /// One connection: posts a driver's reports to the session's loop as messages. There, a report of the current link is
    /// handled; a report of the link being connected is held and handled, in order, once the link is current (see
    /// <see cref="Report"/>); any other is a report of a replaced link and is ignored.
    /// </summary>
    private sealed class Connection : IDeviceListener
    {
        private readonly OnlineSession _session;

        /// <summary>
        /// Acknowledgements posted and not handled yet, oldest first: each posts <see cref="_takeAcknowledged"/> once, which handles
        /// the oldest, so they are handled in the order they came, in order with the other reports, and without a closure each.
        /// </summary>
        private readonly ConcurrentQueue<(int Id, double? Value)> _acknowledged = new();

        /// <summary>The message an acknowledgement posts (one delegate for all).</summary>
        private readonly Action _takeAcknowledged;

        internal Connection(OnlineSession session, IDeviceDriver driver)
        {
            _session = session;
            Driver = driver;
            _takeAcknowledged = TakeAcknowledged;
        }

        internal IDeviceDriver Driver { get; }

        /// <summary>
        /// Its reports that arrived while it was being connected, in order (on the loop only): handled once it is current. Of the
        /// live poses only the latest is kept (<c>IsMotion</c>): the robot is where the last one says.
        /// </summary>
        internal List<(Action Handle, bool IsMotion)> Held { get; } = [];

        // The driver reports the id on the wire; the session maps it to an action (held while connecting, mapped once current).
        public void OnAcknowledged(int id) => OnAcknowledged(id, null);

        public void OnAcknowledged(int id, double value) => OnAcknowledged(id, (double?)value);

        // The busiest report (one per action): one message that allocates nothing, with no handler of its own unless it has to be held.
        private void OnAcknowledged(int id, double? value)
        {
            _acknowledged.Enqueue((id, value));
            _session.Post(_takeAcknowledged);
        }

        private void TakeAcknowledged()
        {
            if (_acknowledged.TryDequeue(out (int Id, double? Value) acknowledged))
            {
                _session.ReceiveAcknowledged(this, acknowledged.Id, acknowledged.Value);
            }
        }

        public void OnMotion(in MotionSample sample)
        {
            MotionSample copy = sample;
            _session.Report(this, () => _session.OnMotion(this, copy), isMotion: true);
        }

        public void OnStopped(MachinaException reason) => _session.Report(this, () => _session.OnStopped(this, reason));

        public void OnResumed() => _session.Report(this, () => _session.OnResumed(this));

        public void OnFailed(int id, string reason, string? code) => _session.Report(this, () => _session.OnFailed(this, id, reason, code));

        public void OnFailedAfter(int executedId, string reason, string? code) =>
            _session.Report(this, () => _session.OnFailedAfter(this, executedId, reason, code));

        public void OnFault(MachinaException error) => _session.Report(this, () => _session.Fault(this, error));
    }

    /// <summary>
    /// Posts a driver's report to the loop and returns: it is handled there, in the order posted, when <paramref name="link"/>
    /// is current, held while <paramref name="link"/> is being connected (a live pose, <paramref name="isMotion"/>, replaces the
    /// one held before) and ignored otherwise. The driver's thread never waits for the loop: when the loop is idle it runs it
    /// (as any poster does), else it goes on reading while the loop's owner handles the report.
    /// </summary>
    private void Report(Connection link, Action handle, bool isMotion = false) => Post(() => Receive(link, handle, isMotion));

    /// <summary>An acknowledgement, as <see cref="Receive"/> handles any report: at once from the current link, else held or ignored.</summary>
    private void ReceiveAcknowledged(Connection link, int id, double? value)
    {
        if (ReferenceEquals(_link, link))
        {
            OnAcknowledged(link, id, value);
        }
        else
        {
            HoldAcknowledged(link, id, value);
        }
    }

    // A method of its own: the closure is then made only here, not on every acknowledgement at the top of the caller.
    private void HoldAcknowledged(Connection link, int id, double? value) => Receive(link, () => OnAcknowledged(link, id, value), isMotion: false);

    private void Receive(Connection link, Action handle, bool isMotion)
    {
        if (ReferenceEquals(_link, link))
        {
            handle();
        }
        else if (ReferenceEquals(Volatile.Read(ref _connecting), link))
        {
            if (isMotion)
            {
                link.Held.RemoveAll(static h => h.IsMotion);
            }
            link.Held.Add((handle, isMotion));
        }
    }
}
