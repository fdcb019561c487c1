using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// <c>speedj(qd, a, t)</c> and <c>speedl(xd, a, t, aRot)</c> (the Script Manual: "Accelerate linearly in joint space and continue
/// with constant joint speed. The time t is optional; if provided the function will return after time t, regardless of the
/// target speed has been reached. If the time t is not provided, the function will return when the target speed is reached").
/// The arm's speed changes evenly from the speeds it has to the ones asked (the leading joint at a) and then stays: the motion
/// goes on after the call returned, until a motion or stop of the same thread takes it over (<c>stopj</c> slows it from that
/// speed), a hold or the program's end stops it where it is, or a joint reaches its position limit, where the arm stops with a
/// protective stop (the safety system's joint position limit).
/// </summary>
internal sealed partial class UrTwinController
{
    /// <summary>The control step of a UR (500 Hz): a speed command takes at least one.</summary>
    internal const double ControlStep = 0.002;

    /// <summary>The runtime error of a motion commanded while another thread's motion is in progress (a UR's message).</summary>
    internal const string AnotherThread = "Another thread is already controlling the robot.";

    private ITimer? _speedTimer;

    /// <summary>How long a speed motion whose end is not known yet is planned for, seconds (a day: longer than any test or session).</summary>
    private const double OpenSeconds = 86_400;

    /// <summary>
    /// Plans a speed motion from where the arm is (<c>at</c>) and how it moves there (where it is <c>step</c> seconds apart,
    /// <c>before</c> and <c>after</c>; all three the same when it stands): its way and how long its speed ramp takes.
    /// </summary>
    private delegate (IUrSpeedWay Way, double Ramp) SpeedPlan(Joints at, Joints before, Joints after, double step);

    /// <summary>
    /// Starts a speed motion towards the joint <paramref name="speeds"/> (degrees per second), the speeds changing evenly from
    /// the ones the arm has over <paramref name="ramp"/> seconds (0: at once), and returns after <paramref name="seconds"/> (0:
    /// when the speed is reached, at least one control step), the arm still moving. <paramref name="cancellation"/> is the
    /// calling thread's: it owns the motion.
    /// </summary>
    /// <exception cref="TwinMotionException">Another, live thread's motion is in progress.</exception>
    public void Speed(double[] speeds, double ramp, double seconds, int line, string function, CancellationToken cancellation) =>
        RunSpeed((at, before, after, step) =>
            (new UrSpeedPath(at, JointSpeeds(before, after, step), speeds, ramp, Arm.Model.MinJoints.ToArray(), Arm.Model.MaxJoints.ToArray()), ramp),
            seconds, line, function, cancellation);

    /// <summary>The joint speeds (degrees per second) of an arm at <paramref name="before"/> and then <paramref name="after"/>, <paramref name="step"/> seconds apart.</summary>
    private static double[] JointSpeeds(Joints before, Joints after, double step)
    {
        double[] speeds = new double[6], a = before.ToArray(), b = after.ToArray();
        for (int i = 0; i < 6; i++)
        {
            speeds[i] = (b[i] - a[i]) / step;
        }
        return speeds;
    }

    /// <summary>
    /// <c>speedl</c>: starts a speed motion of the tool towards <paramref name="xd"/> (m/s, then rad/s as a rotation vector, base
    /// frame), the tool's speed changing evenly from the one it has (its position's at <paramref name="acceleration"/> m/s², its
    /// turn's at <paramref name="turning"/> rad/s², the slower leading) and then held: the tool keeps to its straight line
    /// (<see cref="UrToolSpeedPath"/>). Returns as <see cref="Speed"/> does.
    /// </summary>
    /// <exception cref="TwinMotionException">Another, live thread's motion is in progress.</exception>
    public void ToolSpeed(double[] xd, double acceleration, double turning, double seconds, int line, string function, CancellationToken cancellation) =>
        RunSpeed((at, before, after, step) =>
        {
            Pose from = ToolPose(before), to = ToolPose(after);
            Vector v0 = (to.Position - from.Position) * (1 / step); // mm/s
            RotationVector turn = (to.Rotation * from.Rotation.Inverse()).ToRotationVector();
            var w0 = new Vector(turn.X, turn.Y, turn.Z) * (1 / step); // degrees per second
            Vector v = new Vector(xd[0], xd[1], xd[2]) * 1000, w = new Vector(xd[3], xd[4], xd[5]) * (1 / Radians);
            double move = (v - v0).Length / 1000, spin = (w - w0).Length * Radians;
            double ramp = Math.Max(move > 0 && acceleration > 0 ? move / acceleration : 0, spin > 0 && turning > 0 ? spin / turning : 0);
            return (new UrToolSpeedPath(Arm, at, v0, w0, v, w, ramp), ramp);
        }, seconds, line, function, cancellation);

    /// <summary>Runs a speed motion planned by <paramref name="plan"/> from where the arm is: see <see cref="Speed"/>.</summary>
    private void RunSpeed(SpeedPlan plan, double seconds, int line, string function, CancellationToken cancellation)
    {
        WaitWhileHeld(cancellation);
        if (!TakeCoast(cancellation, false, out Joints at, out Joints before, out Joints after, out double step))
        {
            at = before = after = Arm.Joints;
            step = 1;
        }
        (IUrSpeedWay way, double ramp) = plan(at, before, after, step);
        double wait = seconds > 0 ? seconds : Math.Max(ramp, ControlStep);
        if (!Clock.RealTime)
        {
            // Program time (a verification): the arm is where the speed brought it when the call returns, and stands there.
            way.Extend(wait);
            Arm.MoveTo(way.At(Math.Min(wait, way.LimitSeconds)), wait, line, function, cancellation);
            return;
        }
        // A limit further than a day (a crawl) is planned as a day, like a way whose end is not known yet: the timer looks again.
        double duration = double.IsFinite(way.LimitSeconds) ? Math.Min(way.LimitSeconds, OpenSeconds) : double.IsFinite(way.KnownUntil) ? OpenSeconds : ramp;
        if (duration <= 0)
        {
            Clock.Wait(wait, cancellation); // at rest and asked to stay so: nothing moves
            return;
        }
        var motion = new UrMotion(at, way.At(Math.Min(duration, way.KnownUntil)), 0, Options.Time.GetTimestamp(), duration, 0, way.Over(duration), ownProfile: true) { OpenEnded = true };
        CancellationToken hold;
        lock (_holdGate)
        {
            hold = _holdStop.Token;
            _motion = motion;
            _motionOwner = cancellation;
            double due = Math.Min(way.LimitSeconds, way.KnownUntil);
            if (double.IsFinite(due))
            {
                _speedTimer = Options.Time.CreateTimer(_ => WatchSpeed(motion, way), null, TimerDue(due), Timeout.InfiniteTimeSpan);
            }
        }
        StateChanged?.Invoke();
        using var both = CancellationTokenSource.CreateLinkedTokenSource(cancellation, hold);
        try
        {
            Clock.Wait(wait, both.Token);
        }
        catch (OperationCanceledException) when (!cancellation.IsCancellationRequested)
        {
            WaitWhileHeld(cancellation); // held: the hold stopped the arm; the call returns once the program goes on
        }
        Arm.Record(line, TwinTraceKind.Motion, function, way.At(Math.Min(wait, duration)));
    }

    /// <summary>
    /// The speed motion's timer (on the timer's thread): at the way's limit the arm stops there with a protective stop; before
    /// it, the way is looked at further ahead and the timer set for the end of what is known.
    /// </summary>
    private void WatchSpeed(UrMotion motion, IUrSpeedWay way)
    {
        const double Tick = 1e-6; // closer than a timer can tell apart (a timestamp's tick is 0.1 us): reached
        double elapsed = Options.Time.GetElapsedTime(motion.Started).TotalSeconds;
        if (way.LimitSeconds > elapsed + Tick)
        {
            way.Extend(Math.Max(elapsed, way.KnownUntil)); // a piece further than known, whatever the timer's rounding
        }
        if (way.LimitSeconds <= elapsed + Tick)
        {
            AtLimit(motion, way.LimitReason);
            return;
        }
        double next = Math.Min(way.LimitSeconds, way.KnownUntil);
        lock (_holdGate)
        {
            if (ReferenceEquals(_motion, motion) && double.IsFinite(next))
            {
                _speedTimer?.Change(TimerDue(Math.Max(next - elapsed, Tick)), Timeout.InfiniteTimeSpan);
            }
        }
    }

    /// <summary>
    /// A speed timer's due time: at most <see cref="OpenSeconds"/> ahead (a crawl of 1e-13 rad/s reaches its limit in 10^13 s,
    /// past what a timer takes); the timer looks at the way again when it fires and sets itself for the rest.
    /// </summary>
    private static TimeSpan TimerDue(double seconds) => TimeSpan.FromSeconds(Math.Min(seconds, OpenSeconds));

    /// <summary>A speed motion reached the end of its way (on the timer's thread): the arm stops there with a protective stop.</summary>
    private void AtLimit(UrMotion motion, string reason)
    {
        lock (_holdGate)
        {
            if (!ReferenceEquals(_motion, motion))
            {
                return;
            }
        }
        Pendant.Log($"Protective stop: {reason}");
        RequestProtectiveStop(); // the hold takes the motion: the arm stands at the limit
        TakeCoast(CancellationToken.None, true, out _, out _, out _, out _); // held already (another stop): stop the arm all the same
    }

    /// <summary>Stops the joint-limit timer of the speed motion being taken over, if any.</summary>
    private void StopSpeedTimer()
    {
        ITimer? timer;
        lock (_holdGate)
        {
            (timer, _speedTimer) = (_speedTimer, null);
        }
        timer?.Dispose();
    }
}
