using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// <c>stopj(a)</c> and <c>stopl(a, aRot)</c> (the Script Manual: "Stop (linear in joint space) - decelerate joint speeds to
/// zero", a the joint acceleration of the leading axis; "Stop (linear in tool space) - decelerate tool speed to zero", a the
/// tool acceleration, aRot its rotational one, a when not given). The arm goes on from the speeds it has when the stop is
/// called (a motion whose thread was killed coasts on its plan until then) and slows down evenly to rest: every joint in
/// proportion for stopj, the tool along the straight line it was moving on (turning on about the axis it was turning about)
/// for stopl; the leading one at the acceleration given, the others so that all stop together. The call returns when the arm
/// is at rest, where it stopped.
/// </summary>
internal sealed partial class UrTwinController
{
    /// <summary>How far either side of now (seconds) the speeds of a coasting motion are read.</summary>
    private const double SpeedStep = 0.0005;

    private const double Radians = Math.PI / 180;

    /// <summary>
    /// Stops the arm from the speeds it has now (a coasting motion's: <see cref="Move(Joints, double, double, IUrMotionPath?, bool, int, string, CancellationToken, Joints?, bool)"/>),
    /// slowing down evenly in joint space (<paramref name="tool"/> false: the leading joint at <paramref name="acceleration"/>
    /// rad/s²) or along the tool's line (true: the position at <paramref name="acceleration"/> m/s², the orientation at
    /// <paramref name="rotationAcceleration"/> rad/s², whichever takes longer leading), and returns when the arm is at rest.
    /// Nothing to do when the arm stands. The speed motion of the calling thread (<paramref name="cancellation"/>: <c>speedj</c>,
    /// <c>speedl</c>) is slowed so too.
    /// </summary>
    /// <exception cref="TwinMotionException">Where the arm would stop is beyond a joint limit or out of reach, or another, live
    /// thread's motion is in progress (<see cref="AnotherThread"/>).</exception>
    public void Decelerate(bool tool, double acceleration, double rotationAcceleration, int line, string function, CancellationToken cancellation)
    {
        if (!TakeCoast(cancellation, false, out Joints at, out Joints before, out Joints after, out double step))
        {
            return;
        }
        double[] speeds = JointSpeeds(before, after, step); // degrees per second
        double seconds;
        Joints end;
        Func<double, Joints> path;
        if (!tool)
        {
            seconds = speeds.Max(Math.Abs) * Radians / acceleration;
            end = Ahead(at, speeds, seconds / 2);
            path = f => UrMotion.Lerp(at, end, f);
        }
        else
        {
            Pose from = ToolPose(before), to = ToolPose(after), here = ToolPose(at);
            Vector velocity = (to.Position - from.Position) * (1 / step); // mm/s
            RotationVector turn = (to.Rotation * from.Rotation.Inverse()).ToRotationVector();
            Vector spin = new Vector(turn.X, turn.Y, turn.Z) * (1 / step); // degrees per second, base frame
            seconds = Math.Max(velocity.Length / 1000 / acceleration, spin.Length * Radians / rotationAcceleration);
            var stopAt = new Pose(here.Position + velocity * (seconds / 2), Rotation.FromRotationVector(spin * (seconds / 2)) * here.Rotation);
            end = Arm.Solve(stopAt, Ahead(at, speeds, seconds / 2));
            path = f => f >= 1 ? end : UrBuiltins.Near(Arm, new Pose(here.Position + (stopAt.Position - here.Position) * f,
                UrGeometry.Slerp(here.Rotation, stopAt.Rotation, f)), UrMotion.Lerp(at, end, f));
        }
        if (!(seconds > 0))
        {
            return;
        }
        double total = seconds;
        Move(end, total, 0, t => Slowing(t, total), path, line, function, cancellation, null, true);
    }

    /// <summary>
    /// Ends a coasting motion (its thread was killed or the program stopped, and no stop took it over) where it has brought the
    /// arm now: the arm stands there, suddenly (a UR's program that ends without stopj stops so).
    /// </summary>
    public void SettleCoast() => TakeCoast(CancellationToken.None, false, out _, out _, out _, out _);

    /// <summary>
    /// As <see cref="SettleCoast()"/>, for a motion the thread of <paramref name="caller"/> is about to command: its own speed
    /// motion stops where it is too, and another, live thread's motion in progress refuses it.
    /// </summary>
    /// <exception cref="TwinMotionException">Another, live thread's motion is in progress (<see cref="AnotherThread"/>).</exception>
    public void SettleCoast(CancellationToken caller) => TakeCoast(caller, false, out _, out _, out _, out _);

    /// <summary>
    /// Takes the coasting motion, if any: the arm stands where it is now (<paramref name="at"/>), and <paramref name="before"/>
    /// and <paramref name="after"/> are where the motion put it <paramref name="step"/> seconds apart around now (its speeds).
    /// A speed motion is taken too when <paramref name="caller"/> owns it or when <paramref name="anySpeed"/> (a hold).
    /// False when no motion coasts.
    /// </summary>
    /// <exception cref="TwinMotionException">A live thread other than <paramref name="caller"/> (when given) controls the motion in progress.</exception>
    private bool TakeCoast(CancellationToken caller, bool anySpeed, out Joints at, out Joints before, out Joints after, out double step)
    {
        UrMotion? motion;
        lock (_holdGate)
        {
            motion = _motion is { } moving && (_motionOwner.IsCancellationRequested || (moving.OpenEnded && (anySpeed || _motionOwner == caller)))
                ? moving : null;
            if (motion is null && _motion is not null && caller.CanBeCanceled && _motionOwner != caller && !_motionOwner.IsCancellationRequested)
            {
                throw new TwinMotionException(AnotherThread);
            }
        }
        if (motion is not null)
        {
            StopSpeedTimer();
        }
        at = before = after = default;
        step = 0;
        if (motion is null)
        {
            return false;
        }
        TimeSpan now = Options.Time.GetElapsedTime(motion.Started), half = TimeSpan.FromSeconds(SpeedStep);
        TimeSpan from = now - half < TimeSpan.Zero ? TimeSpan.Zero : now - half, to = now + half > motion.Duration ? motion.Duration : now + half;
        at = motion.At(now);
        (before, after) = to > from ? (motion.At(from), motion.At(to)) : (at, at);
        step = to > from ? (to - from).TotalSeconds : 1;
        Arm.MoveTo(at, 0, 0, "", CancellationToken.None, trace: false); // the arm stands there before the motion ends: no jump back
        EndMotion(motion);
        return true;
    }

    /// <summary>The tool centre point at <paramref name="joints"/> (mm, base frame).</summary>
    private Pose ToolPose(Joints joints) => Arm.FlangeAt(joints) * Arm.ToolCenter;

    /// <summary>The joints <paramref name="seconds"/> on from <paramref name="at"/> at <paramref name="speeds"/> (degrees per second).</summary>
    private static Joints Ahead(Joints at, double[] speeds, double seconds) =>
        new(at.J1 + speeds[0] * seconds, at.J2 + speeds[1] * seconds, at.J3 + speeds[2] * seconds,
            at.J4 + speeds[3] * seconds, at.J5 + speeds[4] * seconds, at.J6 + speeds[5] * seconds);

    /// <summary>The part of the way done <paramref name="t"/> seconds into an even slow-down to rest that takes <paramref name="seconds"/>.</summary>
    private static double Slowing(double t, double seconds)
    {
        double u = Math.Clamp(t / seconds, 0, 1);
        return u * (2 - u);
    }
}
