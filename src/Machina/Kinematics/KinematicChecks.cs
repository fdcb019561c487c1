using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// Pre-flight checks for one motion: is the target reachable within the joint limits, is it near a singularity, and for straight
/// lines, does the arm stay in one configuration and within its joint speeds all the way. Pure functions; nothing is stored.
/// </summary>
public static class KinematicChecks
{
    /// <summary>Axis 5 closer than this to 0° or 180° counts as a wrist singularity (degrees).</summary>
    public const double WristSingularityDegrees = 2;

    /// <summary>An elbow closer than this to fully stretched or folded counts as an elbow singularity (degrees).</summary>
    public const double ElbowSingularityDegrees = 2;

    /// <summary>A wrist point closer than this to axis 1's singular line counts as a shoulder singularity (mm).</summary>
    public const double ShoulderSingularityMm = 20;

    /// <summary>Straight lines are sampled at least every this many millimetres...</summary>
    public const double LinearStepMm = 2;

    /// <summary>...and every this many degrees of flange rotation.</summary>
    public const double LinearStepDegrees = 1;

    /// <summary>A joint jumping more than this between two samples of a straight line means the arm had to change configuration (degrees).</summary>
    public const double FlipJumpDegrees = 30;

    /// <summary>Arcs are also sampled at least every this many degrees of the circle.</summary>
    public const double ArcStepDegrees = 2;

    /// <summary>A joint move to a Cartesian target that turns one joint by more than this is reported (degrees).</summary>
    public const double LargeJointMoveDegrees = 180;

    private const int MaxSamples = 2000;

    /// <summary>Checks a motion to a flange pose. <paramref name="previous"/> is the joint state before the motion (null when unknown).</summary>
    public static IReadOnlyList<KinematicIssue> Check(RobotModel model, Joints? previous, Pose target, KinematicMotion motion, double speedMmPerSecond)
    {
        IReadOnlyList<KinematicIssue> issues = Check(model, previous, target, motion, speedMmPerSecond, Pose.Identity, out _);
        return issues.Count > 0 ? issues : new List<KinematicIssue>();
    }

    /// <summary>
    /// As the public overload, and also gives the joint solution it checked (null when the target cannot be reached within the limits):
    /// for a path (a line, or an arc when <paramref name="arcThrough"/> is given) from known <paramref name="previous"/> joints, the joints
    /// the arm arrives with when it follows the path; for a joint move, the solution closest to <paramref name="previous"/>; with
    /// previous unknown, the first one within the limits. Positions in the sentences are those of <paramref name="tool"/> on the flange
    /// (the TCP the program speaks of; identity for the flange itself). <paramref name="arcThrough"/> is a TCP position.
    /// </summary>
    internal static IReadOnlyList<KinematicIssue> Check(RobotModel model, Joints? previous, Pose target, KinematicMotion motion, double speedMmPerSecond, Pose tool, out Joints? solution, Vector? arcThrough = null)
    {
        solution = null;
        ArgumentNullException.ThrowIfNull(model);
        target.Position.RequireFinite(nameof(target));
        // Made at the first issue: most motions have none, and the cursor keeps a shared empty list for them.
        List<KinematicIssue>? issues = null;
        IKinematics kin = model.Kinematics;
        var solver = (ISolver)kin;
        Affine flange = Affine.FromPose(target);
        Joints? chosen;
        if (previous is Joints p && p.IsFinite && ReferenceEquals(kin.Model, model))
        {
            // The solution closest to the known joints, solved once (every ISolver's Closest is KinematicsCore.ClosestOf of its raw
            // solutions on its own model); the raw solutions are solved again only for a refusal's sentence.
            chosen = solver.Closest(flange, p, out bool reachable);
            if (!reachable)
            {
                return Unreachable(model, target, tool);
            }
        }
        else
        {
            Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
            Span<ArmConfiguration> configs = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
            if (solver.SolveRaw(flange, previous ?? default, raw, configs) == 0)
            {
                return Unreachable(model, target, tool);
            }
            chosen = previous is Joints q ? kin.Closest(target, q) : FirstWithinLimits(kin, target);
        }
        solution = chosen;
        if (chosen is null)
        {
            Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
            Span<ArmConfiguration> configs = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
            int n = solver.SolveRaw(flange, previous ?? default, raw, configs);
            return new List<KinematicIssue> { KinematicsCore.LimitIssue(model, KinematicsCore.NearestToLimits(model, raw[..n]), $"every way to reach {Shown(target, tool)} needs a joint beyond its limits") };
        }
        if (previous is Joints start)
        {
            if (motion == KinematicMotion.Linear || arcThrough is not null)
            {
                // The controller follows the path: the arm arrives with the joints it reaches continuously, not with the solution closest to
                // where it started (the two differ when the path passes near a singularity).
                // The target's solution closest to the start is what the path's first sample solves for when that sample is the target itself.
                Joints? closestToStart = start.IsFinite && ReferenceEquals(kin.Model, model) ? chosen : null;
                if (CheckPath(model, start, target, arcThrough, speedMmPerSecond, tool, ref issues, out SingularityMeasure arrival, closestToStart) is Joints followed)
                {
                    chosen = solution = followed;
                    CheckSingularities(arrival, "at the target", ref issues); // the path's last sample measured these joints already
                    return (IReadOnlyList<KinematicIssue>?)issues ?? NoIssues;
                }
            }
            else
            {
                CheckJointMove(start, chosen.Value, ref issues);
            }
        }
        CheckSingularities(solver.Measure(chosen.Value), "at the target", ref issues);
        return (IReadOnlyList<KinematicIssue>?)issues ?? NoIssues;
    }

    /// <summary>Checks a motion to joint values (degrees). For linear motions the flange follows a straight line to their pose.</summary>
    public static IReadOnlyList<KinematicIssue> Check(RobotModel model, Joints? previous, Joints target, KinematicMotion motion, double speedMmPerSecond)
    {
        ArgumentNullException.ThrowIfNull(model);
        target.RequireFinite(nameof(target));
        List<KinematicIssue>? issues = null;
        if (!model.IsWithinLimits(target))
        {
            (int joint, double limit, _) = KinematicsCore.WorstLimit(model, target);
            return new List<KinematicIssue> { new KinematicIssue(KinematicIssueKind.JointLimit, $"the target joints {target} are beyond the limits ({Violation(model, target)}).") { Joint = joint, Limit = limit } };
        }
        if (motion == KinematicMotion.Linear && previous is Joints start)
        {
            IKinematics kin = model.Kinematics;
            if (CheckPath(model, start, kin.Forward(target), null, speedMmPerSecond, Pose.Identity, ref issues, out _) is Joints arrival
                && kin.ConfigurationOf(arrival) != kin.ConfigurationOf(target))
            {
                Add(ref issues, KinematicIssueKind.ConfigurationFlip,
                    $"the target joints are in {kin.ConfigurationOf(target)} but a straight line from the start arrives in {kin.ConfigurationOf(arrival)} (use a joint move).");
            }
        }
        CheckSingularities(((ISolver)model.Kinematics).Measure(target), "at the target", ref issues);
        return issues ?? new List<KinematicIssue>();
    }

    private static readonly KinematicIssue[] NoIssues = [];

    private static List<KinematicIssue> Unreachable(RobotModel model, Pose target, Pose tool) =>
        [new KinematicIssue(KinematicIssueKind.Unreachable, $"the target {Shown(target, tool)} is out of reach of the {model}.")];

    private static Joints? FirstWithinLimits(IKinematics kin, Pose target)
    {
        Span<Joints> s = stackalloc Joints[KinematicsCore.MaxSolutions];
        return kin.Inverse(target, s) > 0 ? s[0] : null;
    }

    /// <summary>
    /// Follows the tool tip from the pose of <paramref name="start"/> to <paramref name="target"/> (a flange pose) on a straight line, or on
    /// the circle through <paramref name="arcThrough"/>, turning the tool evenly from the start to the end orientation as the
    /// controllers do. Reports where the path leaves the reach or the limits, changes configuration, passes near a singularity, or
    /// asks a joint to move faster than it can; returns the joints at the end of the path (null when the path could not be followed).
    /// </summary>
    /// <remarks>
    /// <paramref name="closestToStart"/>, when known, is the solution of <paramref name="target"/> closest to <paramref name="start"/>
    /// (<see cref="KinematicsCore.ClosestOf"/> of the target's raw solutions): a first sample that is the target to the last bit (a
    /// line short enough for one sample, the common streamed move) takes it instead of solving the target again.
    /// <paramref name="arrival"/> is the singularity measure of the joints returned (default when null).
    /// </remarks>
    private static Joints? CheckPath(RobotModel model, Joints start, Pose target, Vector? arcThrough, double speed, Pose tool, ref List<KinematicIssue>? issues,
        out SingularityMeasure arrival, Joints? closestToStart = null)
    {
        arrival = default;
        IKinematics kin = model.Kinematics;
        var solver = (ISolver)kin;
        // The controller moves the tool tip on the path (the flange swings around it when the tool turns): sample the tip's path and
        // solve for the flange of each sample; the speed is the tip's.
        Pose from = kin.Forward(start) * tool, to = target * tool, toTool = tool.Inverse();
        CircleArc arc = default;
        bool isArc = arcThrough is Vector through && CircleArc.TryCreate(from.Position, through, to.Position, out arc);
        double length = isArc ? arc.Length : Vector.Distance(from.Position, to.Position);
        double turn = from.Rotation.AngleTo(to.Rotation);
        double sweepSteps = isArc ? arc.Sweep * Angles.ToDegrees / ArcStepDegrees : 0;
        int steps = (int)Math.Clamp(Math.Ceiling(Math.Max(Math.Max(length / LinearStepMm, turn / LinearStepDegrees), sweepSteps)), 1, MaxSamples);
        string path = isArc ? "arc" : "line";
        ArmConfiguration startConfig = kin.ConfigurationOf(start);
        double dt = speed > 0 && length > 1e-9 ? length / steps / speed : 0;
        // The joints' speeds are asked only with a time step (the model's property is read once, not per joint and sample).
        bool bySpeed = dt > 0 && model.MaxJointSpeeds is not null;
        Joints max = bySpeed ? model.MaxJointSpeeds!.Value : default;
        double worstRatio = 0;
        int worstJoint = -1;
        Joints last = start;
        for (int i = 1; i <= steps; i++)
        {
            double t = (double)i / steps;
            Vector position = i == steps ? to.Position : isArc ? arc.PointAt(t) : from.Position + (to.Position - from.Position) * t;
            Pose pose = new Pose(position, Slerp(from.Rotation, to.Rotation, t)) * toTool;
            Joints? next = i == 1 && closestToStart is not null && SameBits.Of(pose, target) ? closestToStart : kin.Closest(pose, last);
            if (next is null)
            {
                LeavesPath(model, path, t, pose, last, tool, ref issues);
                return null;
            }
            Joints j = next.Value;
            double jump = 0;
            // Joint by joint on the fields, in the joints' order (the first of equal ratios is the one named).
            Step(0, Math.Abs(j.J1 - last.J1), dt, bySpeed, max.J1, ref jump, ref worstRatio, ref worstJoint);
            Step(1, Math.Abs(j.J2 - last.J2), dt, bySpeed, max.J2, ref jump, ref worstRatio, ref worstJoint);
            Step(2, Math.Abs(j.J3 - last.J3), dt, bySpeed, max.J3, ref jump, ref worstRatio, ref worstJoint);
            Step(3, Math.Abs(j.J4 - last.J4), dt, bySpeed, max.J4, ref jump, ref worstRatio, ref worstJoint);
            Step(4, Math.Abs(j.J5 - last.J5), dt, bySpeed, max.J5, ref jump, ref worstRatio, ref worstJoint);
            Step(5, Math.Abs(j.J6 - last.J6), dt, bySpeed, max.J6, ref jump, ref worstRatio, ref worstJoint);
            (ArmConfiguration config, SingularityMeasure measure) = solver.Assess(j);
            if (jump > FlipJumpDegrees || config != startConfig)
            {
                Add(ref issues, KinematicIssueKind.ConfigurationFlip,
                    $"the arm would have to change configuration {Where(t, path, pose, tool)} (from {startConfig} to {config}, a joint jumps {Num.F(jump, 1)}°): the {path} passes through or very near a position where the arm must flip, which it cannot do smoothly (use a joint move, or move the path away from it).");
            }
            if (IsNearSingularity(measure))
            {
                CheckSingularities(measure, Where(t, path, pose, tool), ref issues);
            }
            last = j;
            arrival = measure;
        }
        if (worstRatio > 1 && model.MaxJointSpeeds is Joints limits)
        {
            Add(ref issues, KinematicIssueKind.JointSpeed,
                $"at {Num.F(speed, 1)} mm/s joint {worstJoint + 1} would need {Num.F(worstRatio * limits[worstJoint], 0)}°/s, above its maximum of {Num.F(limits[worstJoint], 0)}°/s.");
        }
        return last;
    }

    /// <summary>One joint's change <paramref name="d"/> between two samples: the largest jump, and the joint speed's worst ratio to its maximum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Step(int k, double d, double dt, bool bySpeed, double max, ref double jump, ref double worstRatio, ref int worstJoint)
    {
        jump = Math.Max(jump, d);
        if (bySpeed && d / dt / max > worstRatio)
        {
            worstRatio = d / dt / max;
            worstJoint = k;
        }
    }

    /// <summary>The issue of a path sample that has no solution within the limits: out of reach, or a joint beyond its limits.</summary>
    /// <remarks>Its own method: a buffer on the stack in <see cref="CheckPath"/>'s loop kept that method out of tiered compilation.</remarks>
    private static void LeavesPath(RobotModel model, string path, double t, Pose pose, Joints last, Pose tool, ref List<KinematicIssue>? issues)
    {
        Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> cfg = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        bool reachable = ((ISolver)model.Kinematics).SolveRaw(Affine.FromPose(pose), last, raw, cfg) > 0;
        Add(ref issues, reachable ? KinematicIssueKind.JointLimit : KinematicIssueKind.Unreachable,
            reachable ? $"the {path} needs a joint beyond its limits {Where(t, path, pose, tool)}." : $"the {path} leaves the reach of the {model} {Where(t, path, pose, tool)}.");
    }

    /// <summary>A joint move (PTP, MoveJ, movej) to a Cartesian target that swings a joint by more than <see cref="LargeJointMoveDegrees"/>.</summary>
    private static void CheckJointMove(Joints start, Joints end, ref List<KinematicIssue>? issues)
    {
        int widest = 0;
        for (int k = 1; k < Joints.Count; k++)
        {
            if (Math.Abs(end[k] - start[k]) > Math.Abs(end[widest] - start[widest]))
            {
                widest = k;
            }
        }
        double swing = Math.Abs(end[widest] - start[widest]);
        if (swing > LargeJointMoveDegrees)
        {
            Add(ref issues, KinematicIssueKind.LargeJointMove,
                $"to reach this target in a joint move, joint {widest + 1} turns {Num.F(swing, 0)}° (from {Num.F(start[widest], 1)}° to {Num.F(end[widest], 1)}°); make sure the tool and its cables have room to swing.");
        }
    }

    /// <summary>Where a sample of a path is, for messages (built only when there is something to report).</summary>
    private static string Where(double t, string path, Pose pose, Pose tool) => $"{Num.F(t * 100, 0)}% along the {path}, at {Shown(pose, tool)}";

    /// <summary>The position quoted in messages: the tool tip for a flange pose.</summary>
    private static Vector Shown(Pose flange, Pose tool) => (flange * tool).Position;

    private static bool IsNearSingularity(SingularityMeasure m) =>
        m.WristDegrees < WristSingularityDegrees || m.ElbowDegrees < ElbowSingularityDegrees || m.ShoulderMm < ShoulderSingularityMm;

    private static void CheckSingularities(SingularityMeasure m, string where, ref List<KinematicIssue>? issues)
    {
        // At the singular point itself a distance reads "0"; say what it means instead.
        if (m.WristDegrees < WristSingularityDegrees)
        {
            string how = m.WristDegrees < 0.005 ? "axis 5 is exactly straight" : $"axis 5 is only {Num.F(m.WristDegrees, 2)}° from straight";
            Add(ref issues, KinematicIssueKind.WristSingularity, $"{how} {where}, so axes 4 and 6 line up and the controller cannot tell them apart; axes 4 and 6 may spin fast.");
        }
        if (m.ElbowDegrees < ElbowSingularityDegrees)
        {
            string how = m.ElbowDegrees < 0.005 ? "the arm is fully stretched or folded at the elbow" : $"the elbow is only {Num.F(m.ElbowDegrees, 2)}° from fully stretched or folded";
            Add(ref issues, KinematicIssueKind.ElbowSingularity, $"{how} {where}, at the edge of what the arm can reach; it may move slowly or jerkily there.");
        }
        if (m.ShoulderMm < ShoulderSingularityMm)
        {
            string how = m.ShoulderMm < 0.05 ? "the wrist is right on axis 1's singular line" : $"the wrist is only {Num.F(m.ShoulderMm, 1)} mm from axis 1's singular line";
            Add(ref issues, KinematicIssueKind.ShoulderSingularity, $"{how} {where}, where turning axis 1 hardly moves the wrist; axis 1 may spin fast.");
        }
    }

    private static void Add(ref List<KinematicIssue>? issues, KinematicIssueKind kind, string reason)
    {
        issues ??= [];
        foreach (KinematicIssue i in issues)
        {
            if (i.Kind == kind)
            {
                return;
            }
        }
        issues.Add(new KinematicIssue(kind, reason));
    }

    private static string Violation(RobotModel model, Joints j)
    {
        var parts = new List<string>();
        for (int i = 0; i < Joints.Count; i++)
        {
            if (j[i] < model.MinJoints[i] || j[i] > model.MaxJoints[i])
            {
                parts.Add($"joint {i + 1} at {Num.F(j[i], 1)}°, allowed {Num.G(model.MinJoints[i])}° to {Num.G(model.MaxJoints[i])}°");
            }
        }
        return parts.Count > 0 ? string.Join("; ", parts) : "no single joint out of range";
    }

    /// <summary>Spherical interpolation between two rotations (shortest way).</summary>
    internal static Rotation Slerp(Rotation a, Rotation b, double t)
    {
        double dot = a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        double bw = b.W, bx = b.X, by = b.Y, bz = b.Z;
        if (dot < 0)
        {
            dot = -dot; bw = -bw; bx = -bx; by = -by; bz = -bz;
        }
        double wa, wb;
        if (dot > 0.9999995)
        {
            wa = 1 - t; wb = t;
        }
        else
        {
            double theta = Math.Acos(dot), s = Math.Sin(theta);
            wa = Math.Sin((1 - t) * theta) / s; wb = Math.Sin(t * theta) / s;
        }
        return Rotation.FromQuaternion(wa * a.W + wb * bw, wa * a.X + wb * bx, wa * a.Y + wb * by, wa * a.Z + wb * bz);
    }
}
