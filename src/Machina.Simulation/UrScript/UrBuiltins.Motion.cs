using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>Largest joint change (degrees) between two neighbouring points of a straight-line move before it is refused as a flip.</summary>
    private const double MaxJointStepDegrees = 60;

    private static void AddMotion(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "movej", (m, line, a) => MoveJ(m, line, a, "movej"), R("q"), O("a", 1.4), O("v", 1.05), O("t", 0), O("r", 0));
        Add(t, "movel", (m, line, a) => MoveLinear(m, line, a, "movel"), R("pose"), O("a", 1.2), O("v", 0.25), O("t", 0), O("r", 0));
        Add(t, "movep", (m, line, a) => MoveLinear(m, line, [a[0], a[1], a[2], 0, a[3]], "movep"), R("pose"), O("a", 1.2), O("v", 0.25), O("r", 0));
        Add(t, "movec", MoveC, R("pose_via"), R("pose_to"), O("a", 1.2), O("v", 0.25), O("r", 0), O("mode", 0));
        Add(t, "servoj", ServoJ, R("q"), O("a", 0), O("v", 0), O("t", 0.002), O("lookahead_time", 0.1), O("gain", 300));
        Add(t, "stopj", (m, line, a) => Stop(m, line, a, "stopj", tool: false), R("a"));
        Add(t, "stopl", (m, line, a) => Stop(m, line, a, "stopl", tool: true), R("a"), O("aRot", NotGiven));
        // Where the arm is now: part-way through a motion in progress (another thread's, or a speed motion that goes on).
        Add(t, "get_actual_tcp_pose", (m, line, a) => UrGeometry.FromPose(ToolNow(m)));
        Add(t, "get_target_tcp_pose", (m, line, a) => UrGeometry.FromPose(ToolNow(m)));
        Add(t, "get_actual_joint_positions", (m, line, a) => UrGeometry.FromJoints(m.Controller.JointsNow()));
        Add(t, "get_target_joint_positions", (m, line, a) => UrGeometry.FromJoints(m.Controller.JointsNow()));
        Add(t, "get_actual_tcp_speed", (m, line, a) => new UrPose(m.Controller.TcpSpeedNow()));
        Add(t, "get_actual_joint_speeds", (m, line, a) => UrGeometry.FromJoints(m.Controller.JointSpeedsNow()));
        // The CB2 controllers' name (software 1.x, as get_joint_positions): the actual joint speeds, as get_actual_joint_speeds.
        Add(t, "get_joint_speeds", (m, line, a) => UrGeometry.FromJoints(m.Controller.JointSpeedsNow()));
        Add(t, "is_steady", (m, line, a) => UrValue.Box(true));
        Add(t, "set_tcp", SetTcp, R("pose"));
        Add(t, "set_payload", SetPayload, R("m"), O("cog", NotGiven));
        Add(t, "set_payload_mass", (m, line, a) => SetPayload(m, line, [a[0], NotGiven]), R("m"));
        Add(t, "get_forward_kin", ForwardKin, O("q", NotGiven), O("tcp", NotGiven));
        Add(t, "get_inverse_kin", InverseKin, R("x"), O("qnear", NotGiven), O("maxPositionError", 1e-10), O("maxOrientationError", 1e-10), O("tcp", NotGiven));
        Add(t, "get_inverse_kin_has_solution", (m, line, a) => UrValue.Box(TrySolve(m, line, a[0], a[1]) is not null),
            R("pose"), O("qnear", NotGiven), O("maxPositionError", 1e-10), O("maxOrientationError", 1e-10), O("tcp", NotGiven));
        Add(t, "is_within_safety_limits", (m, line, a) => UrValue.Box(TrySolve(m, line, a[0], NotGiven) is not null), R("pose"), O("qnear", NotGiven));
    }

    /// <summary>The tool centre point now (part-way through a motion in progress).</summary>
    private static Pose ToolNow(UrMachine m) => m.Controller.Motion is null ? m.Controller.Arm.Tcp : m.Controller.Arm.FlangeAt(m.Controller.JointsNow()) * m.Controller.Arm.ToolCenter;

    private static double Positive(double value, int line, string function, string parameter) =>
        value > 0 && double.IsFinite(value) ? value : throw new UrRuntimeException(line, $"{function}: argument '{parameter}' must be positive");

    /// <summary>
    /// stopj(a) / stopl(a, aRot): a pending blend finishes at its waypoint; an arm still moving (a motion whose thread was
    /// killed) slows down from the speeds it has now to rest (in joint space, or along the tool's line with aRot, a when not
    /// given, for the turn) and the call returns when it stands, where it stopped (<see cref="UrTwinController.Decelerate"/>).
    /// </summary>
    private static object Stop(UrMachine m, int line, object[] a, string function, bool tool)
    {
        double acceleration = Positive(Num(a, 0, line, function, "a"), line, function, "a");
        double turn = tool && Given(a[1]) ? Positive(Num(a, 1, line, function, "aRot"), line, function, "aRot") : acceleration;
        FinishBlend(m, line);
        Unlocked(m, line, function, (tool, acceleration, turn, line, function),
            static (c, s, token) => { c.Decelerate(s.tool, s.acceleration, s.turn, s.line, s.function, token); return true; });
        return UrNone.Value;
    }

    private static (double A, double V, double T, double R) Profile(object[] a, int line, string function)
    {
        double acc = Num(a, 1, line, function, "a"), v = Num(a, 2, line, function, "v"), time = Num(a, 3, line, function, "t"), r = Num(a, 4, line, function, "r");
        if (time < 0 || r < 0 || !double.IsFinite(time) || !double.IsFinite(r))
        {
            throw new UrRuntimeException(line, $"{function}: 't' and 'r' must be zero or positive");
        }
        if (time == 0 && (!(acc > 0) || !(v > 0) || !double.IsFinite(acc) || !double.IsFinite(v)))
        {
            throw new UrRuntimeException(line, $"{function}: speed 'v' and acceleration 'a' must be positive");
        }
        return (acc, v, time, r);
    }

    private static Joints Solve(UrMachine m, int line, string function, Pose tcp, Joints near)
    {
        try
        {
            return m.Controller.Arm.Solve(tcp, near);
        }
        catch (TwinMotionException e)
        {
            throw new UrRuntimeException(line, $"{function}: {e.Message}");
        }
    }

    private static void Move(UrMachine m, int line, Joints target, double seconds, string function, double rampSeconds = 0, Func<double, Joints>? path = null) =>
        Unlocked(m, line, function, (target, seconds, rampSeconds, path, line, function),
            static (c, s, token) => { c.Move(s.target, s.seconds, s.rampSeconds, s.path, s.line, s.function, token); return true; });

    private static object MoveJ(UrMachine m, int line, object[] a, string function)
    {
        (double acc, double v, double time, _) = Profile(a, line, function);
        FinishBlend(m, line); // the twin blends linear motions only: the arm stops at the last waypoint first
        TakeControl(m, line, function);
        Joints from = m.Controller.Arm.Joints;
        Joints to = a[0] is UrPose pose
            ? Solve(m, line, function, UrGeometry.ToPose(pose.Values, line), from)
            : UrGeometry.ToJoints(Six(a, 0, line, function, "q"), line);
        double distance = UrGeometry.LargestChange(from, to) * Math.PI / 180;
        Move(m, line, to, time > 0 ? time : TwinMotion.TrapezoidSeconds(distance, v, acc), function, time > 0 ? 0 : v / acc);
        return UrNone.Value;
    }

    /// <summary>Solves the inverse kinematics at points along a path, each near the last, and gives the joints at its end.</summary>
    private static Joints FollowLine<TWay>(UrMachine m, int line, string function, Pose start, Pose end, TWay way)
        where TWay : IUrWay
    {
        double mm = (end.Position - start.Position).Length;
        double degrees = TwinRotation.AngleDegrees(start.Rotation, end.Rotation);
        int steps = (int)Math.Clamp(Math.Ceiling(Math.Max(mm / 10, degrees / 5)), 1, 16);
        Joints joints = m.Controller.Arm.Joints;
        // The target itself first, so that an unreachable target is named as such. The path's last point is the target: a path of
        // one step (a move shorter than 10 mm and 5 degrees, every move of a fine toolpath) ends at this solution, not solved twice.
        Joints atEnd = Solve(m, line, function, end, joints);
        for (int k = 1; k <= steps; k++)
        {
            Joints next;
            try
            {
                next = k < steps ? m.Controller.Arm.Solve(way.PoseAt((double)k / steps), joints)
                    : steps == 1 ? atEnd
                    : m.Controller.Arm.Solve(end, joints);
            }
            catch (TwinMotionException e)
            {
                throw new UrRuntimeException(line, FormattableString.Invariant(
                    $"{function}: the straight path leaves the workspace {100.0 * (k - 1) / steps:0}% of the way ({e.Message})"));
            }
            double jump = UrGeometry.LargestChange(joints, next);
            if (jump > MaxJointStepDegrees)
            {
                throw new UrRuntimeException(line, FormattableString.Invariant(
                    $"{function}: the straight path passes near a singularity (a joint would turn {jump:0.#} deg between two close points)"));
            }
            joints = next;
        }
        return joints;
    }

    /// <summary>
    /// movec: the TCP on the circle from where it is through pose_via's position to pose_to at the tool speed v (a trapezoid with
    /// acceleration a), the orientation turning evenly from the current pose to pose_to (mode 0, unconstrained) or kept to the arc's
    /// tangent (mode 1, fixed: pose_to's orientation is not used). A hold stops it on the circle; once released it goes on along it.
    /// </summary>
    private static object MoveC(UrMachine m, int line, object[] a)
    {
        (double acc, double v, _, _) = Profile([null!, a[2], a[3], 0, a[4]], line, "movec");
        FinishBlend(m, line);
        TakeControl(m, line, "movec");
        Pose via = TargetPose(m, a, 0, line, "movec", "pose_via");
        Pose to = TargetPose(m, a, 1, line, "movec", "pose_to");
        double mode = Num(a, 5, line, "movec", "mode");
        if (mode != 0 && mode != 1)
        {
            throw new UrRuntimeException(line, "movec: argument 'mode' must be 0 (unconstrained) or 1 (fixed)");
        }
        TwinArm arm = m.Controller.Arm;
        Pose start = arm.Tcp;
        TwinArc arc = TwinArc.Through(start, via.Position, to, mode == 1 ? TwinArcOrientation.FixedToPath : TwinArcOrientation.Even)
            ?? throw new UrRuntimeException(line, FormattableString.Invariant(
                $"movec: the start, via and end points do not define a circle {TwinArc.NotACircle}"));
        Joints first = arm.Joints;
        Joints last = FollowLine(m, line, "movec", start, arc.End, new UrArcWay(arc));
        Joints Along(double f) => f >= 1 ? last : Near(arm, arc.At(f), UrMotion.Lerp(first, last, f));
        Move(m, line, last, TwinMotion.TrapezoidSeconds(arc.LengthMm / 1000, v, acc), "movec", v / acc, Along);
        return UrNone.Value;
    }

    /// <summary>
    /// servoj: the arm tracks q for t seconds with the servo's lookahead_time and gain (a and v are not used, as on a UR) and goes on
    /// tracking it after the call returned (<see cref="UrTwinController.Servo"/>).
    /// </summary>
    private static object ServoJ(UrMachine m, int line, object[] a)
    {
        Joints to = UrGeometry.ToJoints(Six(a, 0, line, "servoj", "q"), line);
        double time = Num(a, 3, line, "servoj", "t");
        if (!(time > 0) || !double.IsFinite(time))
        {
            throw new UrRuntimeException(line, "servoj: argument 't' must be positive");
        }
        double lookahead = Positive(Num(a, 4, line, "servoj", "lookahead_time"), line, "servoj", "lookahead_time");
        double gain = Positive(Num(a, 5, line, "servoj", "gain"), line, "servoj", "gain");
        FinishBlend(m, line);
        Unlocked(m, line, "servoj", (to, time, lookahead, gain, line),
            static (c, s, token) => { c.Servo(s.to, s.time, s.lookahead, s.gain, s.line, token); return true; });
        return UrNone.Value;
    }

    /// <summary>A motion's target given as a pose, or as joint positions (an array of six), which name the TCP pose they put the arm at.</summary>
    private static Pose TargetPose(UrMachine m, object[] a, int i, int line, string function, string parameter)
    {
        double[] values = Six(a, i, line, function, parameter);
        TwinArm arm = m.Controller.Arm;
        return a[i] is UrList
            ? arm.Model.Kinematics.Forward(UrGeometry.ToJoints(values, line)) * arm.ToolCenter
            : UrGeometry.ToPose(values, line);
    }

    private static object SetTcp(UrMachine m, int line, object[] a)
    {
        FinishBlend(m, line);
        m.Controller.Arm.ToolCenter = UrGeometry.ToPose(Six(a, 0, line, "set_tcp", "pose"), line);
        m.Controller.Arm.Record(line, TwinTraceKind.Tool, "set_tcp");
        return UrNone.Value;
    }

    private static object SetPayload(UrMachine m, int line, object[] a)
    {
        double mass = Num(a, 0, line, "set_payload", "m");
        if (!(mass >= 0) || !double.IsFinite(mass))
        {
            throw new UrRuntimeException(line, "set_payload: the mass 'm' must be zero or positive");
        }
        if (Given(a[1]))
        {
            m.Controller.Modes.PayloadCog = Three(a, 1, line, "set_payload", "cog");
        }
        m.Controller.Arm.PayloadKg = mass;
        return UrNone.Value;
    }

    private static object ForwardKin(UrMachine m, int line, object[] a)
    {
        Joints q = Given(a[0]) ? UrGeometry.ToJoints(Six(a, 0, line, "get_forward_kin", "q"), line) : m.Controller.Arm.Joints;
        Pose tcp = Given(a[1]) ? UrGeometry.ToPose(Six(a, 1, line, "get_forward_kin", "tcp"), line) : m.Controller.Arm.ToolCenter;
        return UrGeometry.FromPose(m.Controller.Arm.Model.Kinematics.Forward(q) * tcp);
    }

    private static Joints? TrySolve(UrMachine m, int line, object pose, object near)
    {
        Pose target = UrGeometry.ToPose(UrValue.Six(pose, line, "the pose"), line);
        Joints reference = Given(near) ? UrGeometry.ToJoints(UrValue.Six(near, line, "qnear"), line) : m.Controller.Arm.Joints;
        return m.Controller.Arm.Model.Kinematics.Closest(target * m.Controller.Arm.ToolCenter.Inverse(), reference);
    }

    private static object InverseKin(UrMachine m, int line, object[] a)
    {
        Pose target = UrGeometry.ToPose(Six(a, 0, line, "get_inverse_kin", "x"), line);
        Joints near = Given(a[1]) ? UrGeometry.ToJoints(Six(a, 1, line, "get_inverse_kin", "qnear"), line) : m.Controller.Arm.Joints;
        Pose tcp = Given(a[4]) ? UrGeometry.ToPose(Six(a, 4, line, "get_inverse_kin", "tcp"), line) : m.Controller.Arm.ToolCenter;
        Joints? solution = m.Controller.Arm.Model.Kinematics.Closest(target * tcp.Inverse(), near);
        return solution is { } q ? UrGeometry.FromJoints(q) : throw new UrRuntimeException(line, "get_inverse_kin: no solution for the pose within the joint limits");
    }
}
