using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>Shared, family-independent parts of inverse kinematics: joint limits, ±360° turns, nearest solution.</summary>
internal static class KinematicsCore
{
    internal const int MaxSolutions = 8;

    /// <summary>Moves each joint to the turn (θ + k·360°) within the limits that is closest to <paramref name="reference"/>; false when a joint has none.</summary>
    /// <remarks>Called for every raw solution of every check (16 times per streamed move of a known arm): joint by joint on the fields, no indexers.</remarks>
    internal static bool FitLimits(RobotModel model, Joints joints, Joints reference, out Joints fitted)
    {
        Joints min = model.MinJoints, max = model.MaxJoints;
        if (FitJoint(joints.J1, reference.J1, min.J1, max.J1, out double j1) && FitJoint(joints.J2, reference.J2, min.J2, max.J2, out double j2)
            && FitJoint(joints.J3, reference.J3, min.J3, max.J3, out double j3) && FitJoint(joints.J4, reference.J4, min.J4, max.J4, out double j4)
            && FitJoint(joints.J5, reference.J5, min.J5, max.J5, out double j5) && FitJoint(joints.J6, reference.J6, min.J6, max.J6, out double j6))
        {
            fitted = new Joints(j1, j2, j3, j4, j5, j6);
            return true;
        }
        fitted = default;
        return false;
    }

    /// <summary>One joint of <see cref="FitLimits"/>: the turn of <paramref name="value"/> within [min, max] closest to <paramref name="ref0"/>.</summary>
    /// <remarks>
    /// The common case first, to the bit what <see cref="FitJointAnyTurn"/> gives: the turn nearest the reference (k = round((ref0 −
    /// value) / 360), the middle one of the three turns the full search tries) is within the range and less than
    /// <see cref="NearTurnDegrees"/> from the reference. The other two are then more than 360° − 179° = 181° from it (less rounding,
    /// below 1e-9° for values and references within ±1e6°), so the search would pick this one too.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool FitJoint(double value, double ref0, double min, double max, out double fitted)
    {
        if (Math.Abs(value) <= 1e6 && Math.Abs(ref0) <= 1e6)
        {
            double nearest = value + 360.0 * Math.Round((ref0 - value) / 360.0);
            if (nearest >= min - 1e-9 && nearest <= max + 1e-9 && Math.Abs(nearest - ref0) < NearTurnDegrees)
            {
                fitted = Math.Clamp(nearest, min, max);
                return true;
            }
        }
        return FitJointAnyTurn(value, ref0, min, max, out fitted);
    }

    /// <summary>How close (degrees) the nearest turn must be to the reference for <see cref="FitJoint"/>'s short way.</summary>
    internal const double NearTurnDegrees = 179;

    /// <summary><see cref="FitJoint"/> by searching the turns: the three around the reference, then the whole range.</summary>
    internal static bool FitJointAnyTurn(double value, double ref0, double min, double max, out double fitted)
    {
        // Nearest turn to the reference, then step into the range if needed.
        double k = Math.Round((ref0 - value) / 360.0);
        double best = double.NaN, bestDistance = double.PositiveInfinity;
        for (double d = k - 1; d <= k + 1; d++)
        {
            double candidate = value + 360.0 * d;
            if (candidate >= min - 1e-9 && candidate <= max + 1e-9)
            {
                double distance = Math.Abs(candidate - ref0);
                if (distance < bestDistance)
                {
                    best = candidate; bestDistance = distance;
                }
            }
        }
        if (double.IsNaN(best))
        {
            // Wide ranges (beyond ±540°) or a reference far away: search the whole range.
            double start = value + 360.0 * Math.Ceiling((min - 1e-9 - value) / 360.0);
            for (double candidate = start; candidate <= max + 1e-9; candidate += 360.0)
            {
                double distance = Math.Abs(candidate - ref0);
                if (distance < bestDistance)
                {
                    best = candidate; bestDistance = distance;
                }
            }
            if (double.IsNaN(best))
            {
                fitted = 0;
                return false;
            }
        }
        fitted = Math.Clamp(best, min, max);
        return true;
    }

    internal static int Inverse(ISolver solver, RobotModel model, Pose flange, Span<Joints> solutions)
    {
        Span<Joints> raw = stackalloc Joints[MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[MaxSolutions];
        int n = solver.SolveRaw(Affine.FromPose(flange), default, raw, configs);
        int count = 0;
        for (int i = 0; i < n && count < solutions.Length; i++)
        {
            // Where two branches meet (straight wrist, stretched elbow, wrist centre on axis 1) they give the same joints: list them once.
            if (FitLimits(model, raw[i], default, out Joints fitted) && !Contains(solutions[..count], fitted))
            {
                solutions[count++] = fitted;
            }
        }
        return count;
    }

    private static bool Contains(ReadOnlySpan<Joints> list, Joints joints)
    {
        foreach (Joints j in list)
        {
            if (j.IsSimilar(joints, 1e-4))
            {
                return true;
            }
        }
        return false;
    }

    internal static IReadOnlyList<Joints> InverseList(ISolver solver, RobotModel model, Pose flange)
    {
        Span<Joints> buffer = stackalloc Joints[MaxSolutions];
        int n = Inverse(solver, model, flange, buffer);
        return buffer[..n].ToArray();
    }

    internal static Joints? Closest(ISolver solver, RobotModel model, Pose flange, Joints current)
    {
        current.RequireFinite(nameof(current));
        return ReferenceEquals(((IKinematics)solver).Model, model)
            ? solver.Closest(Affine.FromPose(flange), current, out _)
            : ClosestOfAll(solver, model, Affine.FromPose(flange), current, out _);
    }

    /// <summary>
    /// <see cref="ClosestOf"/> of every raw solution; <paramref name="reachable"/> is false when there is none (out of reach). What
    /// <see cref="ISolver.Closest"/> gives for a solver that does not narrow its search.
    /// </summary>
    internal static Joints? ClosestOfAll(ISolver solver, RobotModel model, in Affine flange, Joints current, out bool reachable)
    {
        Span<Joints> raw = stackalloc Joints[MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[MaxSolutions];
        int n = solver.SolveRaw(flange, current, raw, configs);
        reachable = n > 0;
        return ClosestOf(model, raw[..n], current);
    }

    /// <summary>
    /// The solution of <see cref="Closest(ISolver, RobotModel, Pose, Joints)"/> from the raw solutions <c>SolveRaw</c> gave for the flange
    /// with <paramref name="current"/> as its reference: a caller that has them already does not solve again.
    /// </summary>
    internal static Joints? ClosestOf(RobotModel model, ReadOnlySpan<Joints> raw, Joints current)
    {
        Joints? best = null;
        double bestCost = double.PositiveInfinity;
        for (int i = 0; i < raw.Length; i++)
        {
            if (!FitLimits(model, raw[i], current, out Joints fitted))
            {
                continue;
            }
            double cost = Cost(fitted, current);
            if (cost < bestCost)
            {
                bestCost = cost; best = fitted;
            }
        }
        return best;
    }

    /// <summary>
    /// Slack on a branch's lower bound (degrees): a fitted joint is its raw value plus whole turns (rounded once) and clamped by at most
    /// 1e-9°, so its true change can be below the bound by far less than this; a branch within the slack is solved.
    /// </summary>
    internal const double BoundMargin = 1e-6;

    /// <summary>The distance (degrees) from <paramref name="value"/> to the nearest of <paramref name="reference"/> ± k·360°.</summary>
    internal static double TurnDistance(double value, double reference)
    {
        double d = value - reference;
        return Math.Abs(d - 360.0 * Math.Round(d / 360.0));
    }

    /// <summary>
    /// The closest solvers' next branch: the unsolved one with the lowest lower <paramref name="bound"/> (the first of equals; a bound of
    /// +∞, a branch that cannot be solved, is never taken), marked solved; −1 when none is left or none could beat or tie
    /// <paramref name="best"/>, the lowest cost found so far, within <see cref="BoundMargin"/>.
    /// </summary>
    internal static int NextBranch(ReadOnlySpan<double> bound, Span<bool> solved, double best)
    {
        int next = -1;
        for (int b = 0; b < bound.Length; b++)
        {
            if (!solved[b] && bound[b] < double.PositiveInfinity && (next < 0 || bound[b] < bound[next]))
            {
                next = b;
            }
        }
        if (next < 0 || bound[next] - BoundMargin > best)
        {
            return -1;
        }
        solved[next] = true;
        return next;
    }

    /// <summary>
    /// The fitted solution of lowest cost, the first of equal ones in solution order (a branch not solved or not fitted has cost
    /// +infinity); null when none fits. The closest solvers' last step.
    /// </summary>
    internal static Joints? Lowest(ReadOnlySpan<double> cost, ReadOnlySpan<Joints> fitted)
    {
        Joints? closest = null;
        double bestCost = double.PositiveInfinity;
        for (int i = 0; i < cost.Length; i++)
        {
            if (cost[i] < bestCost)
            {
                bestCost = cost[i];
                closest = fitted[i];
            }
        }
        return closest;
    }

    /// <summary>How far <paramref name="fitted"/> is from <paramref name="current"/> for <see cref="ClosestOf"/>: the largest joint change plus a thousandth of their sum.</summary>
    internal static double Cost(Joints fitted, Joints current)
    {
        double maxDelta = 0, sum = 0;
        Step(fitted.J1 - current.J1, ref maxDelta, ref sum);
        Step(fitted.J2 - current.J2, ref maxDelta, ref sum);
        Step(fitted.J3 - current.J3, ref maxDelta, ref sum);
        Step(fitted.J4 - current.J4, ref maxDelta, ref sum);
        Step(fitted.J5 - current.J5, ref maxDelta, ref sum);
        Step(fitted.J6 - current.J6, ref maxDelta, ref sum);
        return maxDelta + 1e-3 * sum;

        [MethodImpl(MethodImplOptions.AggressiveInlining)] // a local function with ref arguments is not inlined otherwise: six calls per solution, 48 per solve
        static void Step(double change, ref double maxDelta, ref double sum)
        {
            double d = Math.Abs(change);
            maxDelta = Math.Max(maxDelta, d);
            sum += d;
        }
    }

    internal static Joints? Solve(ISolver solver, RobotModel model, Pose flange, ArmConfiguration configuration)
    {
        Span<Joints> raw = stackalloc Joints[MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[MaxSolutions];
        int n = solver.SolveRaw(Affine.FromPose(flange), default, raw, configs);
        for (int i = 0; i < n; i++)
        {
            if (configs[i] == configuration && FitLimits(model, raw[i], default, out Joints fitted))
            {
                return fitted;
            }
        }
        return null;
    }

    /// <summary>Each solution with every combination of ±360° turns of its joints that stays within the model's limits.</summary>
    internal static IReadOnlyList<Joints> WithEveryTurn(RobotModel model, IReadOnlyList<Joints> solutions)
    {
        var all = new List<Joints>();
        var values = new double[6];
        foreach (Joints solution in solutions)
        {
            AddTurns(model, solution, 0, values, all);
        }
        return all;
    }

    private static void AddTurns(RobotModel model, Joints solution, int axis, double[] values, List<Joints> all)
    {
        if (axis == 6)
        {
            all.Add(Joints.FromArray(values));
            return;
        }
        double value = solution[axis];
        double lowest = Math.Ceiling((model.MinJoints[axis] - value) / 360), highest = Math.Floor((model.MaxJoints[axis] - value) / 360);
        for (double k = lowest; k <= highest; k++)
        {
            values[axis] = k == 0 ? value : value + 360 * k;
            AddTurns(model, solution, axis + 1, values, all);
        }
    }

    /// <summary>
    /// Null when the flange pose has a solution within the limits; otherwise why not (out of reach, or the limit passed by the nearest
    /// way of reaching it). Positions in the sentence are those of <paramref name="tool"/> on the flange.
    /// </summary>
    internal static KinematicIssue? WhyNoSolution(ISolver solver, RobotModel model, Pose flange, Pose tool)
    {
        flange.Position.RequireFinite(nameof(flange));
        Span<Joints> raw = stackalloc Joints[MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[MaxSolutions];
        int n = solver.SolveRaw(Affine.FromPose(flange), default, raw, configs);
        Vector shown = (flange * tool).Position;
        if (n == 0)
        {
            return new KinematicIssue(KinematicIssueKind.Unreachable, $"the target {shown} is out of reach of the {model}.");
        }
        for (int i = 0; i < n; i++)
        {
            if (FitLimits(model, raw[i], default, out _))
            {
                return null;
            }
        }
        return LimitIssue(model, NearestToLimits(model, raw[..n]), $"every way to reach {shown} needs a joint beyond its limits");
    }

    /// <summary>A joint-limit issue for <paramref name="joints"/>: <paramref name="what"/>, then the joint furthest past its limit and by how much.</summary>
    internal static KinematicIssue LimitIssue(RobotModel model, Joints joints, string what)
    {
        (int joint, double limit, double excess) = WorstLimit(model, joints);
        string reason = $"{what}: the nearest needs joint {joint} at {Num.F(joints[joint - 1], 1)}°, {Num.F(excess, 1)}° past its limit of {Num.G(limit)}° (allowed {Num.G(model.MinJoints[joint - 1])}° to {Num.G(model.MaxJoints[joint - 1])}°).";
        return new KinematicIssue(KinematicIssueKind.JointLimit, reason) { Joint = joint, Limit = limit };
    }

    /// <summary>The joint (1 to 6) furthest past its limit, that limit and by how much (degrees).</summary>
    internal static (int Joint, double Limit, double Excess) WorstLimit(RobotModel model, Joints joints)
    {
        int worst = 0;
        double worstExcess = 0, limit = model.MaxJoints[0];
        for (int i = 0; i < Joints.Count; i++)
        {
            double min = model.MinJoints[i], max = model.MaxJoints[i];
            double excess = joints[i] < min ? min - joints[i] : joints[i] > max ? joints[i] - max : 0;
            if (excess > worstExcess)
            {
                worst = i; worstExcess = excess; limit = joints[i] < min ? min : max;
            }
        }
        return (worst + 1, limit, worstExcess);
    }

    /// <summary>
    /// Of geometric solutions that all break a limit, the one that breaks them least (smallest total excess, each joint on the ±360°
    /// turn closest to its range): the way to reach the pose that is nearest to being allowed.
    /// </summary>
    internal static Joints NearestToLimits(RobotModel model, ReadOnlySpan<Joints> raw)
    {
        Joints best = raw[0];
        double bestExcess = double.PositiveInfinity;
        Span<double> v = stackalloc double[Joints.Count];
        foreach (Joints solution in raw)
        {
            double excess = 0;
            for (int i = 0; i < Joints.Count; i++)
            {
                double min = model.MinJoints[i], max = model.MaxJoints[i], value = solution[i];
                double bestValue = value, bestJointExcess = double.PositiveInfinity;
                for (int k = -2; k <= 2; k++)
                {
                    double candidate = value + 360.0 * k;
                    double e = candidate < min ? min - candidate : candidate > max ? candidate - max : 0;
                    if (e < bestJointExcess)
                    {
                        bestJointExcess = e; bestValue = candidate;
                    }
                }
                v[i] = bestValue;
                excess += bestJointExcess;
            }
            if (excess < bestExcess)
            {
                bestExcess = excess; best = Joints.FromArray(v);
            }
        }
        return best;
    }

    internal static bool IsWithinLimits(RobotModel model, Joints joints)
    {
        for (int i = 0; i < Joints.Count; i++)
        {
            if (!(joints[i] >= model.MinJoints[i] - 1e-9 && joints[i] <= model.MaxJoints[i] + 1e-9))
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>Wraps radians to degrees in (−180°, 180°].</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // six per solution, two solutions per branch solved, and four for a closest solve's bounds
    internal static double WrapDegrees(double radians)
    {
        double d = radians * Angles.ToDegrees;
        // Inside (−180°, 180°) what IEEERemainder gives is the angle itself: no fmod (a solver wraps six angles of each solution).
        return d > -180.0 && d < 180.0 ? d : WrapOutside(d);
    }

    /// <summary><see cref="WrapDegrees"/> of an angle (degrees) not inside (−180°, 180°).</summary>
    private static double WrapOutside(double d)
    {
        d = Math.IEEERemainder(d, 360.0);
        return d <= -180.0 ? d + 360.0 : d;
    }
}
