using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal sealed partial class UrTwinController
{
    private readonly Lock _holdGate = new();
    private TaskCompletionSource? _held;
    private CancellationTokenSource _holdStop = new();
    private UrMotion? _motion;

    /// <summary>
    /// The cancellation of the thread whose motion <see cref="_motion"/> is: once it is cancelled (<c>kill</c>, or the program
    /// stopped) the motion coasts on its plan until a stop takes it over (<see cref="Decelerate"/>) or the arm is settled
    /// where it is (<see cref="SettleCoast()"/>).
    /// </summary>
    private CancellationToken _motionOwner;

    /// <summary>
    /// Completed when the motion in progress ends (<see cref="Standing"/>): made only while a motion is in progress and something
    /// waits for its end (a pause, a stop on the path), so a motion costs nothing more.
    /// </summary>
    private TaskCompletionSource? _standing;

    /// <summary>True while the program is held (a protective stop or a pause): the arm stands, the program waits.</summary>
    public bool IsHeld
    {
        get
        {
            lock (_holdGate)
            {
                return _held is not null;
            }
        }
    }

    /// <summary>The motion in progress, or null.</summary>
    public UrMotion? Motion
    {
        get
        {
            lock (_holdGate)
            {
                return _motion;
            }
        }
    }

    /// <summary>The joints now: part-way through the motion in progress (on its speed profile), or where the arm stands.</summary>
    public Joints JointsNow()
    {
        UrMotion? motion = Motion;
        return motion is null ? Arm.Joints : motion.At(Options.Time.GetElapsedTime(motion.Started));
    }

    /// <summary>
    /// The joint speeds now, degrees per second: those of the motion in progress on its speed profile (where it puts the arm a
    /// millisecond either side of now, one side at its ends), zero when the arm stands.
    /// </summary>
    public Joints JointSpeedsNow()
    {
        if (!TryStepNow(out Joints a, out Joints b, out double seconds))
        {
            return default;
        }
        return new Joints((b.J1 - a.J1) / seconds, (b.J2 - a.J2) / seconds, (b.J3 - a.J3) / seconds, (b.J4 - a.J4) / seconds, (b.J5 - a.J5) / seconds, (b.J6 - a.J6) / seconds);
    }

    /// <summary>
    /// The tool centre point's speed now in the base frame, in UR's units: x, y, z in m/s, then the turn per second as a rotation
    /// vector (rad/s); zeros when the arm stands. From the same two instants as <see cref="JointSpeedsNow"/>.
    /// </summary>
    public double[] TcpSpeedNow()
    {
        if (!TryStepNow(out Joints a, out Joints b, out double seconds))
        {
            return new double[6];
        }
        Pose from = Arm.Model.Kinematics.Forward(a) * Arm.ToolCenter, to = Arm.Model.Kinematics.Forward(b) * Arm.ToolCenter;
        Vector move = to.Position - from.Position;
        RotationVector turn = (to.Rotation * from.Rotation.Inverse()).ToRotationVector();
        double radians = Math.PI / 180;
        return [move.X / 1000 / seconds, move.Y / 1000 / seconds, move.Z / 1000 / seconds, turn.X * radians / seconds, turn.Y * radians / seconds, turn.Z * radians / seconds];
    }

    /// <summary>Where the motion in progress puts the arm a millisecond before and after now (within the motion), and the seconds between; false when the arm stands.</summary>
    private bool TryStepNow(out Joints before, out Joints after, out double seconds)
    {
        before = after = default;
        seconds = 0;
        UrMotion? motion = Motion;
        if (motion is null)
        {
            return false;
        }
        TimeSpan now = Options.Time.GetElapsedTime(motion.Started), step = TimeSpan.FromMilliseconds(1);
        TimeSpan from = now - step < TimeSpan.Zero ? TimeSpan.Zero : now - step, to = now + step > motion.Duration ? motion.Duration : now + step;
        seconds = (to - from).TotalSeconds;
        if (seconds <= 0)
        {
            return false;
        }
        before = motion.At(from);
        after = motion.At(to);
        return true;
    }

    /// <summary>
    /// Holds the program, as a protective stop or a pause does: a motion in progress stops where the arm is, and the program
    /// waits before its next motion or socket read until <see cref="Release"/>. False when it is already held.
    /// </summary>
    public bool Hold()
    {
        CancellationTokenSource stop;
        lock (_holdGate)
        {
            if (_held is not null)
            {
                return false;
            }
            _held = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            stop = _holdStop;
        }
        stop.Cancel();
        // A motion whose thread was killed stops where it is, as a held one does, and so does a speed motion (speedj, speedl).
        TakeCoast(CancellationToken.None, true, out _, out _, out _, out _);
        StateChanged?.Invoke();
        return true;
    }

    /// <summary>Ends <see cref="Hold"/>: the program goes on (an interrupted motion finishes from where it stopped). False when not held.</summary>
    public bool Release()
    {
        TaskCompletionSource? held;
        lock (_holdGate)
        {
            held = _held;
            if (held is null)
            {
                return false;
            }
            _held = null;
            _holdStop = new CancellationTokenSource();
        }
        held.TrySetResult();
        StateChanged?.Invoke();
        return true;
    }

    /// <summary>Ends <paramref name="motion"/> when it is still the one in progress: the arm stands, and what waits for that is told.</summary>
    private void EndMotion(UrMotion motion)
    {
        TaskCompletionSource? standing = null;
        lock (_holdGate)
        {
            if (ReferenceEquals(_motion, motion))
            {
                _motion = null;
                (standing, _standing) = (_standing, null);
            }
        }
        standing?.TrySetResult();
    }

    /// <summary>Waits while the program is held (cancelled when the program stops).</summary>
    public void WaitWhileHeld(CancellationToken cancellation) => TwinWait.WhilePaused(_holdGate, ref _held, cancellation);

    /// <summary>
    /// Waits until no motion is in progress, at most <paramref name="timeout"/> (a hold reaches the motion at once: the program's
    /// thread records where the arm stands); true when the arm stands. <see cref="OperationCanceledException"/> when
    /// <paramref name="cancellation"/> ends the wait first. It blocks the calling thread: a thread-pool thread should await
    /// <see cref="WaitUntilStandingAsync"/>.
    /// </summary>
    public bool WaitUntilStanding(TimeSpan timeout, CancellationToken cancellation = default) => TwinWait.For(Standing(), timeout, cancellation);

    /// <summary>
    /// As <see cref="WaitUntilStanding"/> without holding a thread while it waits (the dashboard's <c>pause</c>, answered on a
    /// thread-pool thread); true when the arm stands, false after <paramref name="timeout"/>.
    /// </summary>
    public async Task<bool> WaitUntilStandingAsync(TimeSpan timeout, CancellationToken cancellation)
    {
        Task standing = Standing();
        if (!standing.IsCompleted)
        {
            try
            {
                await standing.WaitAsync(timeout, cancellation).ConfigureAwait(false);
            }
            catch (TimeoutException)
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>A task that completes when no motion is in progress (completed already when none is).</summary>
    private Task Standing()
    {
        lock (_holdGate)
        {
            return _motion is null ? Task.CompletedTask : (_standing ??= new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously)).Task;
        }
    }

    /// <summary>
    /// Moves the arm from where it is to <paramref name="target"/> in <paramref name="seconds"/>, along <paramref name="path"/>
    /// (joints at a fraction of the way; null: straight in joint space) with a trapezoid profile whose ramps take
    /// <paramref name="rampSeconds"/>. A hold stops it part-way; once released it finishes from there.
    /// </summary>
    public void Move(Joints target, double seconds, double rampSeconds, Func<double, Joints>? path, int line, string function, CancellationToken cancellation) =>
        Move(target, seconds, rampSeconds, null, path, line, function, cancellation, null, true);

    /// <summary>
    /// As the other <c>Move</c>, with the motion's own speed <paramref name="profile"/> (seconds after the start to the part of the
    /// way done; null: the trapezoid), traced at <paramref name="traced"/> joints (null: the target) or not at all when
    /// <paramref name="trace"/> is false. A motion that a hold interrupted finishes from rest on the trapezoid.
    /// </summary>
    /// <returns>True when the motion ran as planned, false when a hold interrupted it (it then ends at rest).</returns>
    public bool Move(Joints target, double seconds, double rampSeconds, Func<double, double>? profile, Func<double, Joints>? path, int line, string function,
        CancellationToken cancellation, Joints? traced, bool trace) =>
        Move(target, seconds, rampSeconds, path is null ? null : new UrDelegatePath(path, profile), profile is not null, line, function, cancellation, traced, trace);

    /// <summary>
    /// As the other <c>Move</c>, along <paramref name="path"/> (null: straight in joint space) on its own speed profile when
    /// <paramref name="ownProfile"/> (else the trapezoid).
    /// </summary>
    /// <returns>True when the motion ran as planned, false when a hold interrupted it (it then ends at rest).</returns>
    public bool Move(Joints target, double seconds, double rampSeconds, IUrMotionPath? path, bool ownProfile, int line, string function,
        CancellationToken cancellation, Joints? traced, bool trace)
    {
        Arm.RequireWithinLimits(target);
        // A motion whose thread was killed, not stopped by stopj/stopl, or this thread's own speed motion: this one starts where it
        // has brought the arm. Another, live thread's motion in progress refuses this one.
        SettleCoast(cancellation);
        Joints from = Arm.Joints;
        double done = 0; // fraction of the way already behind
        bool planned = true;
        while (true)
        {
            WaitWhileHeld(cancellation);
            CancellationToken hold;
            double span = seconds * (1 - done);
            var motion = new UrMotion(from, target, done, Options.Time.GetTimestamp(), Clock.RealTime ? span : 0, Clock.RealTime ? Math.Min(rampSeconds, span / 2) : 0, path,
                planned && ownProfile);
            lock (_holdGate)
            {
                hold = _holdStop.Token;
                _motion = motion;
                _motionOwner = cancellation;
            }
            using var both = CancellationTokenSource.CreateLinkedTokenSource(cancellation, hold);
            bool coasts = false;
            try
            {
                Arm.MoveTo(target, span, line, function, both.Token, traced, trace);
                return planned;
            }
            catch (OperationCanceledException) when (!cancellation.IsCancellationRequested)
            {
                // Held part-way: the arm stands where the motion had brought it.
                Joints at = motion.At(Options.Time.GetElapsedTime(motion.Started));
                done = motion.FractionAt(Options.Time.GetElapsedTime(motion.Started));
                Arm.MoveTo(at, 0, line, function + " (stopped)", cancellation);
                from = at;
                planned = false;
            }
            catch (OperationCanceledException) when (Clock.RealTime && span > 0)
            {
                // Killed part-way (its thread, or the program stopped): the arm does not stop by itself. The motion stays in
                // progress on its plan, coasting, until stopj/stopl decelerates it from the speeds it has then, or another
                // motion, a hold or the program's end settles it where it is (ur_rtde and UR's client library stop an
                // asynchronous motion so: kill its thread, then stopj(a); without the stopj the robot stops suddenly).
                coasts = true;
                throw;
            }
            finally
            {
                if (!coasts)
                {
                    EndMotion(motion);
                }
            }
        }
    }
}
