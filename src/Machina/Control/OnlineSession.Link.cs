namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>
    /// One connection: routes a driver's reports to the session, ignoring them once the connection is replaced. Reports that
    /// arrive during the handshake, before the connection is current, are kept (one guard, <see cref="KeepUntilReady"/>) and
    /// applied in <see cref="ConnectAsync"/> once the cursors are set: acknowledgements in order, the latest live pose, a stop
    /// not followed by a resume, the first failure and the first fault.
    /// </summary>
    private sealed class Connection(OnlineSession session, IDeviceDriver driver) : IDeviceListener
    {
        private volatile bool _isReady;

        internal IDeviceDriver Driver { get; } = driver;

        /// <summary>Set (under the session lock) once the handshake is done and the cursors are initialised.</summary>
        internal bool IsReady
        {
            get => _isReady;
            set => _isReady = value;
        }

        /// <summary>A fault reported before the connection became current.</summary>
        internal MachinaException? EarlyFault { get; private set; }

        /// <summary>Acknowledgements that arrived before the connection became current (controller ids), in order.</summary>
        internal List<int>? Early { get; set; }

        /// <summary>The latest live pose reported before the connection became current (the monitor's first report).</summary>
        internal MotionSample? EarlyMotion { get; private set; }

        /// <summary>A stop reported before the connection became current and not followed by a resume; applied once it is.</summary>
        internal MachinaException? EarlyStop { get; private set; }

        /// <summary>A failure reported before the connection became current (wire id, reason, code); applied once it is.</summary>
        internal (int Id, string Reason, string? Code)? EarlyFailure { get; private set; }

        /// <summary>
        /// The one guard of every report: before the connection is current, <paramref name="keep"/> records the report (under the
        /// session lock, so that <see cref="ConnectAsync"/> sees it) and true is returned; afterwards false (the report goes on).
        /// Once current, a connection never becomes not current again, so the check needs the lock only until then.
        /// </summary>
        private bool KeepUntilReady<T>(T report, Action<Connection, T> keep)
        {
            if (_isReady)
            {
                return false;
            }
            lock (session._gate)
            {
                if (_isReady)
                {
                    return false;
                }
                keep(this, report);
                return true;
            }
        }

        public void OnAcknowledged(int id)
        {
            if (!KeepUntilReady(id, static (c, i) => (c.Early ??= []).Add(i)))
            {
                session.OnAcknowledged(this, id);
            }
        }

        public void OnMotion(in MotionSample sample)
        {
            if (!KeepUntilReady(sample, static (c, s) => c.EarlyMotion = s))
            {
                session.OnMotion(this, sample);
            }
        }

        public void OnStopped(MachinaException reason)
        {
            if (!KeepUntilReady(reason, static (c, r) => c.EarlyStop = r))
            {
                session.OnStopped(this, reason);
            }
        }

        public void OnResumed()
        {
            if (!KeepUntilReady(0, static (c, _) => c.EarlyStop = null))
            {
                session.OnResumed(this);
            }
        }

        public void OnFailed(int id, string reason, string? code)
        {
            if (!KeepUntilReady((id, reason, code), static (c, f) => c.EarlyFailure ??= f))
            {
                session.OnFailed(this, id, reason, code);
            }
        }

        public void OnFault(MachinaException error)
        {
            if (!KeepUntilReady(error, static (c, e) => c.EarlyFault ??= e))
            {
                session.Fault(this, error);
            }
        }
    }
}
