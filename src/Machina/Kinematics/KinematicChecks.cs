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

    private const int MaxSamples = 2000;

    /// <summary>Checks a motion to a flange pose. <paramref name="previous"/> is the joint state before the motion (null when unknown).</summary>
    public static IReadOnlyList<KinematicIssue> Check(RobotModel model, Joints? previous, Pose target, KinematicMotion motion, double speedMmPerSecond) =>
        Check(model, previous, target, motion, speedMmPerSecond, Pose.Identity, out _);

    /// <summary>
    /// As the public overload, and also gives the joint solution it checked: closest to <paramref name="previous"/>, or the first one within
    /// the limits when previous is null (null when the target cannot be reached within the limits). Positions in the sentences are those of
    /// <paramref name="tool"/> on the flange (the TCP the program speaks of; identity for the flange itself).
    /// </summary>
    internal static IReadOnlyList<KinematicIssue> Check(RobotModel model, Joints? previous, Pose target, KinematicMotion motion, double speedMmPerSecond, Pose tool, out Joints? solution)
    {
        solution = null;
        ArgumentNullException.ThrowIfNull(model);
        target.Position.RequireFinite(nameof(target));
        var issues = new List<KinematicIssue>();
        IKinematics kin = model.Kinematics;
        var solver = (ISolver)kin;
        Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        int n = solver.SolveRaw(Affine.FromPose(target), previous ?? default, raw, configs);
        if (n == 0)
        {
            issues.Add(new KinematicIssue(KinematicIssueKind.Unreachable, $"the target {Shown(target, tool)} is out of reach of the {model}."));
            return issues;
        }
        Joints? chosen = previous is Joints p ? kin.Closest(target, p) : FirstWithinLimits(kin, target);
        solution = chosen;
        if (chosen is null)
        {
            issues.Add(new KinematicIssue(KinematicIssueKind.JointLimit, $"every way to reach {Shown(target, tool)} needs a joint beyond its limits ({Violation(model, raw[0])})."));
            return issues;
        }
        if (motion == KinematicMotion.Linear && previous is Joints start)
        {
            CheckLine(model, start, target, chosen.Value, speedMmPerSecond, tool, issues);
        }
        CheckSingularities(solver.Measure(chosen.Value), "at the target", issues);
        return issues;
    }

    /// <summary>Checks a motion to joint values (degrees). For linear motions the flange follows a straight line to their pose.</summary>
    public static IReadOnlyList<KinematicIssue> Check(RobotModel model, Joints? previous, Joints target, KinematicMotion motion, double speedMmPerSecond)
    {
        ArgumentNullException.ThrowIfNull(model);
        target.RequireFinite(nameof(target));
        var issues = new List<KinematicIssue>();
        if (!model.IsWithinLimits(target))
        {
            issues.Add(new KinematicIssue(KinematicIssueKind.JointLimit, $"the target joints {target} are beyond the limits ({Violation(model, target)})."));
            return issues;
        }
        if (motion == KinematicMotion.Linear && previous is Joints start)
        {
            CheckLine(model, start, model.Kinematics.Forward(target), target, speedMmPerSecond, Pose.Identity, issues);
        }
        CheckSingularities(((ISolver)model.Kinematics).Measure(target), "at the target", issues);
        return issues;
    }

    private static Joints? FirstWithinLimits(IKinematics kin, Pose target)
    {
        Span<Joints> s = stackalloc Joints[KinematicsCore.MaxSolutions];
        return kin.Inverse(target, s) > 0 ? s[0] : null;
    }

    private static void CheckLine(RobotModel model, Joints start, Pose target, Joints end, double speed, Pose tool, List<KinematicIssue> issues)
    {
        IKinematics kin = model.Kinematics;
        var solver = (ISolver)kin;
        // The controller moves the tool tip on the straight line (the flange swings around it when the tool turns): sample the tip's
        // line and solve for the flange of each sample; the speed is the tip's.
        Pose from = kin.Forward(start) * tool, to = target * tool, toTool = tool.Inverse();
        double length = Vector.Distance(from.Position, to.Position);
        double turn = from.Rotation.AngleTo(to.Rotation);
        int steps = (int)Math.Clamp(Math.Ceiling(Math.Max(length / LinearStepMm, turn / LinearStepDegrees)), 1, MaxSamples);
        ArmConfiguration startConfig = kin.ConfigurationOf(start);
        if (kin.ConfigurationOf(end) != startConfig)
        {
            Add(issues, KinematicIssueKind.ConfigurationFlip,
                $"the target needs {kin.ConfigurationOf(end)} but the arm starts with {startConfig}; a straight line cannot change it (use a joint move).");
        }
        double dt = speed > 0 && length > 1e-9 ? length / steps / speed : 0;
        double worstRatio = 0;
        int worstJoint = -1;
        Joints last = start;
        for (int i = 1; i <= steps; i++)
        {
            double t = (double)i / steps;
            Pose pose = new Pose(from.Position + (to.Position - from.Position) * t, Slerp(from.Rotation, to.Rotation, t)) * toTool;
            Joints? next = kin.Closest(pose, last);
            if (next is null)
            {
                Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
                Span<ArmConfiguration> cfg = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
                bool reachable = solver.SolveRaw(Affine.FromPose(pose), last, raw, cfg) > 0;
                Add(issues, reachable ? KinematicIssueKind.JointLimit : KinematicIssueKind.Unreachable,
                    reachable ? $"the line needs a joint beyond its limits {Where(t, pose, tool)}." : $"the line leaves the reach of the {model} {Where(t, pose, tool)}.");
                return;
            }
            Joints j = next.Value;
            double jump = 0;
            for (int k = 0; k < Joints.Count; k++)
            {
                double d = Math.Abs(j[k] - last[k]);
                jump = Math.Max(jump, d);
                if (dt > 0 && model.MaxJointSpeeds is Joints max && d / dt / max[k] > worstRatio)
                {
                    worstRatio = d / dt / max[k];
                    worstJoint = k;
                }
            }
            if (jump > FlipJumpDegrees || kin.ConfigurationOf(j) != startConfig)
            {
                Add(issues, KinematicIssueKind.ConfigurationFlip, $"the arm would have to change configuration {Where(t, pose, tool)} (a joint jumps {Num.F(jump, 1)}°).");
            }
            SingularityMeasure measure = solver.Measure(j);
            if (IsNearSingularity(measure))
            {
                CheckSingularities(measure, Where(t, pose, tool), issues);
            }
            last = j;
        }
        if (worstRatio > 1 && model.MaxJointSpeeds is Joints limits)
        {
            Add(issues, KinematicIssueKind.JointSpeed,
                $"at {Num.F(speed, 1)} mm/s joint {worstJoint + 1} would need {Num.F(worstRatio * limits[worstJoint], 0)}°/s, above its maximum of {Num.F(limits[worstJoint], 0)}°/s.");
        }
    }

    /// <summary>Where a sample of a line is, for messages (built only when there is something to report).</summary>
    private static string Where(double t, Pose pose, Pose tool) => $"{Num.F(t * 100, 0)}% along the line, at {Shown(pose, tool)}";

    /// <summary>The position quoted in messages: the tool tip for a flange pose.</summary>
    private static Vector Shown(Pose flange, Pose tool) => (flange * tool).Position;

    private static bool IsNearSingularity(SingularityMeasure m) =>
        m.WristDegrees < WristSingularityDegrees || m.ElbowDegrees < ElbowSingularityDegrees || m.ShoulderMm < ShoulderSingularityMm;

    private static void CheckSingularities(SingularityMeasure m, string where, List<KinematicIssue> issues)
    {
        if (m.WristDegrees < WristSingularityDegrees)
        {
            Add(issues, KinematicIssueKind.WristSingularity, $"axis 5 is within {Num.F(m.WristDegrees, 2)}° of straight {where}; axes 4 and 6 may spin fast.");
        }
        if (m.ElbowDegrees < ElbowSingularityDegrees)
        {
            Add(issues, KinematicIssueKind.ElbowSingularity, $"the elbow is within {Num.F(m.ElbowDegrees, 2)}° of fully stretched or folded {where}.");
        }
        if (m.ShoulderMm < ShoulderSingularityMm)
        {
            Add(issues, KinematicIssueKind.ShoulderSingularity, $"the wrist is {Num.F(m.ShoulderMm, 1)} mm from axis 1's singular line {where}; axis 1 may spin fast.");
        }
    }

    private static void Add(List<KinematicIssue> issues, KinematicIssueKind kind, string reason)
    {
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
