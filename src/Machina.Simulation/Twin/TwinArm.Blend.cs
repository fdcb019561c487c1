namespace Machina.Simulation.Twin;

/// <summary>
/// Zone blends between linear motions (ABB zonedata, KUKA approximate positioning), shaped as <see cref="BlendModel"/> says so that
/// the cycle-time estimate and the twin agree: a linear motion with a zone returns to the program when the arm enters the zone of
/// its waypoint (the controller's program pointer runs ahead); the next linear motion rounds the corner from there; anything else
/// (<see cref="FinishBlend"/>) first lets the arm slow down within the zone and stop at the waypoint.
/// </summary>
internal sealed partial class TwinArm
{
    private TwinBlend? _blend;

    /// <summary>The corner the arm may round now (its last linear motion returned in the zone of its waypoint), or null.</summary>
    public TwinBlend? PendingBlend
    {
        get
        {
            lock (_gate)
            {
                return _blend;
            }
        }
    }

    /// <summary>
    /// The corner the arm may round now (<see cref="PendingBlend"/>) or, when there is none, the joints now and the tool centre point
    /// at them (<see cref="Now"/>; default when there is a corner), in one look at the gate: a Cartesian KRL motion took it for each.
    /// </summary>
    public TwinBlend? PendingBlendOrNow(out Joints joints, out Pose tcp)
    {
        TwinBlend? blend;
        Pose flange;
        bool known;
        lock (_gate)
        {
            blend = _blend;
            if (blend is not null)
            {
                (joints, tcp) = (default, default);
                return blend;
            }
            joints = JointsNow();
            known = KeptFlange(joints, out flange);
        }
        tcp = (known ? flange : Forward(joints)) * ToolCenter;
        return null;
    }

    private TwinBlend? TakeBlend()
    {
        lock (_gate)
        {
            TwinBlend? blend = _blend;
            _blend = null;
            return blend;
        }
    }

    /// <summary>
    /// Lets the arm finish a pending blend: from the zone's entry it slows down to stop at the waypoint (a stop point after all:
    /// the program waits, ends, or its next motion cannot blend). The waypoint was traced when its motion returned; not again.
    /// </summary>
    public void FinishBlend(CancellationToken cancellation)
    {
        if (TakeBlend() is not { } blend)
        {
            return;
        }
        double seconds = BlendModel.StopSeconds(blend.Radius, blend.Speed, blend.Acceleration);
        Joints start = Joints;
        Joints Along(double f) => Near(new Pose(blend.Entry.Position + (blend.Corner.Position - blend.Entry.Position) * f,
            KinematicChecks.Slerp(blend.Entry.Rotation, blend.Corner.Rotation, f)), Lerp(start, blend.CornerJoints, f));
        MoveTo(blend.CornerJoints, seconds, blend.Line, blend.Text + " (to its waypoint)", cancellation, trace: false, path: Along);
    }

    /// <summary>
    /// Runs a linear motion that may round corners: it blends from a pending blend (or starts from rest where the arm stands) and,
    /// when it has a zone, returns as the arm enters it, leaving a pending blend; the trace keeps its waypoint as programmed.
    /// </summary>
    public void MoveLinear(TwinLinearMove move, int line, string text, CancellationToken cancellation)
    {
        RequireWithinLimits(move.Joints);
        Pose target = move.Target;
        double v = move.Speed, a = move.Acceleration;
        // Where the arm stands, read once: no motion runs while its own task plans the next one (the joints, the pending corner
        // and the flange pose kept for the joints in one look at the gate; the tool centre is a pose product).
        Joints here;
        TwinBlend? pending;
        Pose flange;
        bool known;
        lock (_gate)
        {
            here = JointsNow();
            pending = _blend;
            known = KeptFlange(here, out flange);
        }
        Pose from = pending?.Corner ?? (known ? flange : Forward(here)) * ToolCenter;
        double metres = (target.Position - from.Position).Length / 1000;
        bool blendable = metres >= BlendModel.MinLength && v > 0 && !BlendModel.TurnDominates(move.PlainSeconds, metres, v, a);
        if (!blendable)
        {
            FinishBlend(cancellation); // the tool only turns, or turns slower than it travels: the arm stops at the last waypoint first
            MoveTo(move.Joints, move.PlainSeconds, line, text, cancellation, linear: true);
            return;
        }
        TwinBlend? blend = TakeBlend();
        Pose start = blend?.Corner ?? (pending is null ? from : FlangeAt(here) * ToolCenter);
        Joints first = blend?.CornerJoints ?? here;
        // The blend around the last waypoint (m): from the zone's entry past the waypoint to the exit leg along this motion.
        double exitLeg = blend is null ? 0 : Math.Min(blend.Radius, metres / 2);
        Pose exit = blend is null ? start : TwinBlendedLine.Straight(start, target, exitLeg / metres); // no blend: not used
        double blendLength = blend is null ? 0 : BlendModel.Length(blend.Entry.Position / 1000, start.Position / 1000, exit.Position / 1000);
        double startSpeed = blend?.Speed ?? 0;
        double blendSeconds = blend is null ? 0 : blendLength / startSpeed;
        // This motion's own zone, where it returns to the program.
        double radius = move.MayBlend ? BlendModel.Radius(move.ZoneMm / 1000, metres) : 0;
        double straight = metres - exitLeg - radius;
        double entrySpeed = radius > 0 ? BlendModel.EntrySpeed(straight, startSpeed, v, a, radius) : 0;
        if (!(entrySpeed > 0))
        {
            radius = 0;
            straight = metres - exitLeg;
        }
        SpeedProfile profile = SpeedProfile.Plan(straight, startSpeed, v, entrySpeed, a);
        double total = blendLength + straight;
        var way = new TwinBlendedLine(start, target, exit, blend, metres, exitLeg, blendLength); // s: metres along this motion's way
        Joints end = radius > 0 ? Near(way.At(total), Lerp(first, move.Joints, (metres - radius) / metres)) : move.Joints;
        double seconds = blendSeconds + profile.Seconds;
        // The path is made only when the arm is part-way along it (an interpolated or woken motion): a motion in one step needs none.
        // Without a zone of its own the motion ends at the joints checked above: not looked at again.
        bool reached = MoveTo(end, seconds, line, text, cancellation, move.Joints, true, true, new BlendedPath(this, way, total, here, end), null, within: radius == 0);
        if (radius > 0 && reached) // a cleared path ends it early: the arm stands where it stopped, nothing to blend
        {
            lock (_gate)
            {
                _blend = new TwinBlend(way.At(total), target, move.Joints, radius, entrySpeed, a, line, text);
            }
        }
    }

    /// <summary>A blended linear motion's path (fraction of the way to joints, each solved near the joint-space interpolation), as values until it is made.</summary>
    private readonly struct BlendedPath(TwinArm arm, TwinBlendedLine way, double total, Joints start, Joints end) : ITwinPath
    {
        public Func<double, Joints> Make() => new Along(arm, way, total, start, end).At;
    }

    private sealed class Along(TwinArm arm, TwinBlendedLine way, double total, Joints start, Joints end)
    {
        public Joints At(double f) => arm.Near(way.At(f * total), Lerp(start, end, f));
    }

    private Joints Near(Pose tcp, Joints near)
    {
        try
        {
            return Solve(tcp, near);
        }
        catch (TwinMotionException)
        {
            return near;
        }
    }

    private static Joints Lerp(Joints a, Joints b, double t) => new(a.J1 + (b.J1 - a.J1) * t, a.J2 + (b.J2 - a.J2) * t, a.J3 + (b.J3 - a.J3) * t,
        a.J4 + (b.J4 - a.J4) * t, a.J5 + (b.J5 - a.J5) * t, a.J6 + (b.J6 - a.J6) * t);
}
