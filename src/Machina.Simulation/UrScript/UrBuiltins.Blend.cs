using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>Linear motions and their blends (<see cref="BlendModel"/>): <c>movel</c> and <c>movep</c> with a blend radius <c>r</c>.</summary>
internal static partial class UrBuiltins
{
    /// <summary>
    /// Lets the arm finish a pending blend (it stops at the waypoint): before a wait of the program thread that moved, or before any
    /// thread's non-linear motion, tool change or motion that cannot blend (<paramref name="anyThread"/>).
    /// </summary>
    private static void FinishBlend(UrMachine m, int line, bool anyThread = true)
    {
        UrBlend? blend = m.Controller.PendingBlend;
        if (blend is null || (!anyThread && blend.Thread != Environment.CurrentManagedThreadId) || m.Controller.TakeBlend() is not { } taken)
        {
            return;
        }
        Unlocked(m, line, taken.Function, taken, static (c, t, token) => { c.FinishBlend(t, token); return true; });
    }

    /// <summary>A read that finds nothing to read waits: the arm finishes its pending blend first.</summary>
    private static void FinishBlendBeforeWaiting(UrMachine m, int line, UrSocket socket)
    {
        if (m.Controller.PendingBlend is not null && !socket.HasData)
        {
            FinishBlend(m, line, anyThread: false);
        }
    }

    /// <summary>True when this motion may end in a blend: always in a program without sockets, else only when asked and the next instruction is there.</summary>
    private static bool MayBlend(UrMachine m) =>
        m.Sockets.Count == 0 || (m.Controller.Options.BlendWhileStreaming && m.Sockets.Values.Any(s => s.HasData));

    private static object MoveLinear(UrMachine m, int line, object[] a, string function)
    {
        (double acc, double v, double time, double r) = Profile(a, line, function);
        TakeControl(m, line, function);
        TwinArm arm = m.Controller.Arm;
        Pose target = a[0] is UrList list && list.Items.Length == 6 && a[0] is not UrPose
            ? arm.Model.Kinematics.Forward(UrGeometry.ToJoints(Six(a, 0, line, function, "pose"), line)) * arm.ToolCenter
            : UrGeometry.ToPose(Six(a, 0, line, function, "pose"), line);
        UrBlend? blend = m.Controller.PendingBlend;
        if (blend is not null && (time > 0 || (target.Position - blend.Corner.Position).Length / 1000 < BlendModel.MinLength))
        {
            FinishBlend(m, line); // a timed motion or one that only turns the tool does not blend: the arm stops first
        }
        blend = m.Controller.TakeBlend();
        Pose start = blend?.Corner ?? arm.Tcp; // where the segment begins: the waypoint the arm blends around, or where it stands
        Joints first = blend?.CornerJoints ?? arm.Joints;
        var way = new UrLinearPath(arm, start, target);
        Joints last = FollowLine(m, line, function, start, target, way);
        double lengthMm = (target.Position - start.Position).Length;
        double metres = lengthMm / 1000;
        if (metres < BlendModel.MinLength)
        {
            double angle = TwinRotation.AngleBetween(start.Rotation, target.Rotation);
            var turn = new UrTurnPath(arm, way, first, last);
            Move(m, line, last, time > 0 ? time : TwinMotion.TrapezoidSeconds(angle, v, acc), function, time > 0 ? 0 : v / acc, turn.JointsAt);
            return UrNone.Value;
        }
        // The blend around the last waypoint (m): from the zone's entry past the waypoint to the exit leg along this segment.
        double exitLeg = blend is null ? 0 : Math.Min(blend.Radius, metres / 2);
        double blendLength = blend is null ? 0 : BlendModel.Length(blend.Entry.Position / 1000, start.Position / 1000, way.PoseAt(exitLeg / metres).Position / 1000);
        double startSpeed = blend?.Speed ?? 0;
        double blendSeconds = blend is null ? 0 : blendLength / startSpeed;
        // This motion's own zone, where it returns to the program.
        double radius = time > 0 || !MayBlend(m) ? 0 : BlendModel.Radius(r, metres);
        WarnOverlaps(m, line, function, blend, time > 0 || !MayBlend(m) ? 0 : r, lengthMm);
        double straight = metres - exitLeg - radius;
        double entrySpeed = radius > 0 ? BlendModel.EntrySpeed(straight, startSpeed, v, acc, radius) : 0;
        if (!(entrySpeed > 0))
        {
            radius = 0;
            straight = metres - exitLeg;
        }
        SpeedProfile profile = SpeedProfile.Plan(straight, startSpeed, v, radius > 0 ? entrySpeed : 0, acc);
        way.Blend = blend;
        way.Metres = metres;
        way.ExitLeg = exitLeg;
        way.BlendLength = blendLength;
        way.BlendSeconds = blendSeconds;
        way.StartSpeed = startSpeed;
        way.Profile = profile;
        way.Total = blendLength + straight;
        way.End = radius > 0 ? Near(arm, way.At(way.Total), UrMotion.Lerp(first, last, (metres - radius) / metres)) : last;
        way.StartJoints = arm.Joints;
        double seconds = time > 0 ? time : blendSeconds + profile.Seconds;
        bool planned = Unlocked(m, line, function, (way, seconds, ramp: time > 0 ? 0 : v / acc, exact: time <= 0, line, function, last),
            static (c, s, token) => c.Move(s.way.End, s.seconds, s.ramp, s.way, s.exact, s.line, s.function, token, s.last, true));
        if (radius > 0)
        {
            m.Controller.PendingBlend = new UrBlend(way.At(way.Total), target, last, radius, planned ? entrySpeed : 0, v, acc, Environment.CurrentManagedThreadId, line, function);
            if (!planned)
            {
                FinishBlend(m, line); // a hold stopped the arm: it goes on to its waypoint from rest
            }
        }
        return UrNone.Value;
    }

    /// <summary>
    /// Blends cannot overlap: UR's manual says a warning is logged in the Log tab when two do, and the program runs on. The twin
    /// logs one on its pendant for each radius it shortens to half of this motion of <paramref name="lengthMm"/>: the last
    /// motion's blend that reaches past this motion's middle, and this motion's own radius <paramref name="r"/> (m) beyond it.
    /// </summary>
    private static void WarnOverlaps(UrMachine m, int line, string function, UrBlend? blend, double r, double lengthMm)
    {
        double half = lengthMm / 2;
        if (blend is not null && blend.Radius * 1000 > half)
        {
            m.Controller.Pendant.Log($"Warning: line {Machina.Num.I(line)}: {function}: the blend of line {Machina.Num.I(blend.Line)} ({Mm(blend.Radius * 1000)} mm) " +
                $"overlaps this motion ({Mm(lengthMm)} mm long): blends cannot overlap; it blends with {Mm(half)} mm");
        }
        if (r * 1000 > half)
        {
            m.Controller.Pendant.Log($"Warning: line {Machina.Num.I(line)}: {function}: the blend radius {Mm(r * 1000)} mm is more than half of this motion " +
                $"({Mm(lengthMm)} mm long): blends cannot overlap; it blends with {Mm(half)} mm");
        }
    }

    private static string Mm(double mm) => Machina.Num.G(Math.Round(mm, 3));

    /// <summary>The joints that put the tool at <paramref name="pose"/>, nearest to <paramref name="near"/> (those joints when there are none).</summary>
    internal static Joints Near(TwinArm arm, Pose pose, Joints near)
    {
        try
        {
            return arm.Solve(pose, near);
        }
        catch (TwinMotionException)
        {
            return near;
        }
    }
}
