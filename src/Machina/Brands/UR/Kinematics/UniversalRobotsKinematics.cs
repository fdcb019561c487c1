namespace Machina;

/// <summary>
/// Kinematics of Universal Robots arms (six revolute joints, offset wrist) from UR's published DH table, with an analytical inverse
/// that returns all eight solutions. Poses are the controller's tool0 flange in its "base" frame; joints are in degrees.
/// </summary>
public sealed class UniversalRobotsKinematics : IKinematics, ISolver
{
    private const double HalfPi = Math.PI / 2;
    private readonly UniversalRobotsDh _dh;

    internal UniversalRobotsKinematics(RobotModel model, UniversalRobotsDh dh)
    {
        Model = model;
        _dh = dh;
    }

    /// <inheritdoc/>
    public RobotModel Model { get; }

    /// <summary>The DH lengths of this arm, in mm.</summary>
    public UniversalRobotsDh Parameters => _dh;

    /// <inheritdoc/>
    public Pose Forward(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        return ForwardAffine(joints).ToPose();
    }

    /// <summary>Where the arm's joints are for these joint values: base, shoulder, elbow, wrists 1 to 3, flange.</summary>
    internal Vector[] LinkPoints(Joints j)
    {
        j.RequireFinite(nameof(j));
        const double r = Angles.ToRadians;
        Affine[] steps =
        [
            Affine.Dh(j.J1 * r, _dh.D1, 0, 0, 1), Affine.Dh(j.J2 * r, 0, _dh.A2, 1, 0), Affine.Dh(j.J3 * r, 0, _dh.A3, 1, 0),
            Affine.Dh(j.J4 * r, _dh.D4, 0, 0, 1), Affine.Dh(j.J5 * r, _dh.D5, 0, 0, -1), Affine.Dh(j.J6 * r, _dh.D6, 0, 1, 0),
        ];
        var points = new Vector[7];
        Affine t = Affine.Identity;
        points[0] = Vector.Zero;
        for (int i = 0; i < 6; i++)
        {
            t *= steps[i];
            points[i + 1] = new Vector(t.Px, t.Py, t.Pz);
        }
        return points;
    }

    private Affine ForwardAffine(Joints j)
    {
        const double r = Angles.ToRadians;
        return Affine.Dh(j.J1 * r, _dh.D1, 0, 0, 1)
            * Affine.Dh(j.J2 * r, 0, _dh.A2, 1, 0)
            * Affine.Dh(j.J3 * r, 0, _dh.A3, 1, 0)
            * Affine.Dh(j.J4 * r, _dh.D4, 0, 0, 1)
            * Affine.Dh(j.J5 * r, _dh.D5, 0, 0, -1)
            * Affine.Dh(j.J6 * r, _dh.D6, 0, 1, 0);
    }

    /// <inheritdoc/>
    public int Inverse(Pose flange, Span<Joints> solutions) => KinematicsCore.Inverse(this, Model, flange, solutions);

    /// <inheritdoc/>
    public IReadOnlyList<Joints> Inverse(Pose flange) => KinematicsCore.InverseList(this, Model, flange);

    /// <inheritdoc/>
    public Joints? Closest(Pose flange, Joints current) => KinematicsCore.Closest(this, Model, flange, current);

    /// <inheritdoc/>
    public Joints? Solve(Pose flange, ArmConfiguration configuration) => KinematicsCore.Solve(this, Model, flange, configuration);

    /// <inheritdoc/>
    public bool IsWithinLimits(Joints joints) => KinematicsCore.IsWithinLimits(Model, joints);

    /// <inheritdoc/>
    public KinematicIssue? WhyNoSolution(Pose flange) => KinematicsCore.WhyNoSolution(this, Model, flange, Pose.Identity);

    /// <inheritdoc/>
    /// <remarks>
    /// The shoulder is "left" when the wrist centre is ahead of axis 1 in the arm's plane (<see cref="WristReach"/> &gt; 0): the angle
    /// between axis 1's direction and the wrist centre, less 90°, has the sine −R/√(R² + d4²). No forward kinematics: the checks of a
    /// streamed move ask this three times.
    /// </remarks>
    public ArmConfiguration ConfigurationOf(Joints joints) =>
        new(WristReach(joints) > 0, Math.Sin(joints.J3 * Angles.ToRadians) > 0, Math.Sin(joints.J5 * Angles.ToRadians) < 0);

    SingularityMeasure ISolver.Measure(Joints joints) =>
        MeasureOf(Math.Sin(joints.J5 * Angles.ToRadians), Math.Sin(joints.J3 * Angles.ToRadians), WristReach(joints));

    /// <remarks>The two share sin θ5, sin θ3 and the wrist's reach: taken once (a checked path's every sample asks both).</remarks>
    (ArmConfiguration Configuration, SingularityMeasure Measure) ISolver.Assess(Joints joints)
    {
        double sin5 = Math.Sin(joints.J5 * Angles.ToRadians), sin3 = Math.Sin(joints.J3 * Angles.ToRadians), reach = WristReach(joints);
        return (new ArmConfiguration(reach > 0, sin3 > 0, sin5 < 0), MeasureOf(sin5, sin3, reach));
    }

    private SingularityMeasure MeasureOf(double sin5, double sin3, double reach)
    {
        double wrist = Math.Asin(Math.Min(1, Math.Abs(sin5))) * Angles.ToDegrees;
        double elbow = Math.Asin(Math.Min(1, Math.Abs(sin3))) * Angles.ToDegrees;
        // The wrist centre's distance from axis 1 is √(R² + d4²) (R along the arm's plane, d4 across it).
        double shoulder = Math.Abs(Math.Sqrt(reach * reach + _dh.D4 * _dh.D4) - Math.Abs(_dh.D4));
        return new SingularityMeasure(wrist, elbow, shoulder);
    }

    /// <summary>
    /// Where the wrist centre (frame 5's origin, the flange less d6 along its axis) is along the arm's plane: R = a2·cos θ2 +
    /// a3·cos(θ2 + θ3) + d5·sin(θ2 + θ3 + θ4), so that it lies at (R·cos θ1 + d4·sin θ1, R·sin θ1 − d4·cos θ1) in the base's XY.
    /// </summary>
    private double WristReach(Joints j)
    {
        const double r = Angles.ToRadians;
        double t2 = j.J2 * r, t23 = t2 + j.J3 * r;
        return _dh.A2 * Math.Cos(t2) + _dh.A3 * Math.Cos(t23) + _dh.D5 * Math.Sin(t23 + j.J4 * r);
    }

    int ISolver.SolveRaw(in Affine t, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations)
    {
        if (!TryReach(t, out double phi1, out double phi2))
        {
            return 0;
        }
        int count = 0;
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            Shoulder arm = ShoulderOf(t, phi1, phi2, shoulder);
            Turned turned = TurnedOf(t, arm);
            for (int wrist = 0; wrist < 2; wrist++)
            {
                if (!TryElbows(t, arm, turned, wrist, reference, out Elbows elbows))
                {
                    continue;
                }
                for (int elbow = 0; elbow < 2; elbow++)
                {
                    joints[count] = SolutionOf(arm, elbows, elbow);
                    configurations[count++] = new ArmConfiguration(shoulder == 1, elbow == 1, wrist == 1);
                }
            }
        }
        return count;
    }

    /// <remarks>
    /// The same solution as <see cref="KinematicsCore.ClosestOf"/> of <c>SolveRaw</c>, to the bit, without solving every branch. Axis 1 of
    /// each shoulder and axis 5 of each wrist come first (an arc tangent per shoulder); they bound the cost of the branch's two elbow
    /// solutions from below (a joint's change is at least its distance to the reference modulo 360°). The (shoulder, wrist) pair with the
    /// lowest bound is solved first, another only when its bound does not exceed the best cost found; an opened pair's axis 3 raises the
    /// bound of each of its elbows, and an elbow is solved only when that bound does not exceed the best cost either. The choice is then
    /// made over the solved ones in <c>SolveRaw</c>'s order with the same strict comparison, so ties go where they went.
    /// </remarks>
    Joints? ISolver.Closest(in Affine t, in Joints reference, out bool reachable)
    {
        reachable = false;
        if (!TryReach(t, out double phi1, out double phi2))
        {
            return null;
        }
        Span<Shoulder> arms = stackalloc Shoulder[2];
        Span<Turned> turned = stackalloc Turned[2];
        Span<bool> opened = stackalloc bool[2];
        Span<double> bound = stackalloc double[4];
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            Shoulder arm = arms[shoulder] = ShoulderOf(t, phi1, phi2, shoulder);
            double axis1 = KinematicsCore.TurnDistance(KinematicsCore.WrapDegrees(arm.T1), reference.J1);
            for (int wrist = 0; wrist < 2; wrist++)
            {
                double b = Math.Max(axis1, KinematicsCore.TurnDistance(KinematicsCore.WrapDegrees(wrist == 0 ? arm.T5Abs : -arm.T5Abs), reference.J5));
                // A bound that is not a number proves nothing: that pair is solved first.
                bound[shoulder * 2 + wrist] = double.IsNaN(b) ? double.NegativeInfinity : b;
            }
        }
        // Fitted solutions by SolveRaw's order (shoulder, wrist, elbow); cost +∞ where not solved or beyond the limits.
        Span<Joints> fitted = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<double> cost = stackalloc double[KinematicsCore.MaxSolutions];
        cost.Fill(double.PositiveInfinity);
        Span<bool> solved = stackalloc bool[4];
        double best = double.PositiveInfinity;
        for (int round = 0; round < 4; round++)
        {
            int next = KinematicsCore.NextBranch(bound, solved, best);
            if (next < 0)
            {
                break;
            }
            int shoulder = next >> 1, wrist = next & 1;
            if (!opened[shoulder])
            {
                turned[shoulder] = TurnedOf(t, arms[shoulder]);
                opened[shoulder] = true;
            }
            if (!TryElbows(t, arms[shoulder], turned[shoulder], wrist, reference, out Elbows elbows))
            {
                continue;
            }
            reachable = true;
            // Each elbow's bound with its axis 3; the lower one first.
            double first = Math.Max(bound[next], KinematicsCore.TurnDistance(KinematicsCore.WrapDegrees(-elbows.T3Abs), reference.J3));
            double second = Math.Max(bound[next], KinematicsCore.TurnDistance(KinematicsCore.WrapDegrees(elbows.T3Abs), reference.J3));
            int lower = second < first ? 1 : 0;
            for (int k = 0; k < 2; k++)
            {
                int elbow = k == 0 ? lower : 1 - lower;
                if ((elbow == 0 ? first : second) - KinematicsCore.BoundMargin > best)
                {
                    continue;
                }
                int i = next * 2 + elbow;
                Joints raw = SolutionOf(arms[shoulder], elbows, elbow);
                cost[i] = KinematicsCore.FitLimits(Model, raw, reference, out fitted[i]) ? KinematicsCore.Cost(fitted[i], reference) : double.PositiveInfinity;
                best = Math.Min(best, cost[i]);
            }
        }
        return KinematicsCore.Lowest(cost, fitted);
    }

    /// <summary>One shoulder's axis 1, its sine and cosine, and what gives axis 5 of both wrists.</summary>
    private readonly record struct Shoulder(double T1, double S1, double C1, double Ux, double Uy, double S5Abs, double T5Abs);

    /// <summary>What a shoulder's two wrists share once one of them is solved: T01⁻¹ · T, and θ5's sine and cosine.</summary>
    private readonly record struct Turned(Affine T1t, double SinT5Abs, double CosT5);

    /// <summary>One (shoulder, wrist) pair's axes 5 and 6 and what its two elbows share.</summary>
    private readonly record struct Elbows(double T5, double T6, double T3Abs, double TowardsWrist, double Arm234, double Bend);

    /// <summary>The wrist centre's bearing and the shoulder's offset angle; false when the wrist centre is inside axis 1's cylinder.</summary>
    private bool TryReach(in Affine t, out double phi1, out double phi2)
    {
        double d4 = _dh.D4, d6 = _dh.D6;
        double px = t.Px - d6 * t.R02, py = t.Py - d6 * t.R12;
        double r = Math.Sqrt(px * px + py * py);
        if (!(r >= Math.Abs(d4) - 1e-9) || r == 0)
        {
            phi1 = phi2 = 0;
            return false;
        }
        phi1 = Math.Atan2(py, px);
        phi2 = Math.Acos(Math.Clamp(d4 / r, -1, 1));
        return true;
    }

    // Each sine and cosine below is taken once: Math.SinCos gives Math.Sin's and Math.Cos's bits, and the solutions that differ only in
    // the sign of an angle (θ5 of the two wrists, θ3 of the two elbows) take sin(−x) = −sin(x), cos(−x) = cos(x) and
    // atan2(−y, x) = −atan2(y, x), which hold to the bit (UniversalRobotsSolveBitsTests compares with the full computation).
    private static Shoulder ShoulderOf(in Affine t, double phi1, double phi2, int shoulder)
    {
        double t1 = phi1 + (shoulder == 0 ? phi2 : -phi2) + HalfPi;
        (double s1, double c1) = Math.SinCos(t1);
        // The unit vector (s1, −c1, 0) seen from the flange is (s5·cos θ6, −s5·sin θ6, cos θ5). Taking θ5 with atan2 from it (rather than
        // acos of the flange position, which equals cos θ5 exactly) keeps full precision near the straight wrist θ5 = 0.
        double ux = t.R00 * s1 - t.R10 * c1, uy = t.R01 * s1 - t.R11 * c1, c5 = t.R02 * s1 - t.R12 * c1;
        double s5Abs = Math.Sqrt(ux * ux + uy * uy);
        return new Shoulder(t1, s1, c1, ux, uy, s5Abs, Math.Atan2(s5Abs, c5));
    }

    private Turned TurnedOf(in Affine t, in Shoulder arm)
    {
        (double sinT5Abs, double cosT5) = Math.SinCos(arm.T5Abs);
        // T01⁻¹ · T, the same for both wrists.
        return new Turned(Affine.Dh(arm.C1, arm.S1, _dh.D1, 0, 0, 1).InverseRigid() * t, sinT5Abs, cosT5);
    }

    /// <summary>One wrist's axes 5 and 6 and its elbow triangle; false when the elbow cannot reach (no solution for this pair).</summary>
    private bool TryElbows(in Affine t, in Shoulder arm, in Turned turned, int wrist, in Joints reference, out Elbows elbows)
    {
        double a2 = _dh.A2, a3 = _dh.A3;
        double t5 = wrist == 0 ? arm.T5Abs : -arm.T5Abs;
        double sinT5 = wrist == 0 ? turned.SinT5Abs : -turned.SinT5Abs;
        double sign = wrist == 0 ? 1 : -1;
        // Straight wrist: θ6 is free (axes 2, 3 and 4 make up for it); keep the reference's.
        double t6 = arm.S5Abs < 1e-12 ? reference.J6 * Angles.ToRadians : Math.Atan2(-arm.Uy * sign, arm.Ux * sign);
        (double sinT6, double cosT6) = Math.SinCos(t6);
        // Frame 1 → 4: T14 = T01⁻¹ · T · T56⁻¹ · T45⁻¹
        Affine t14 = turned.T1t * Affine.Dh(cosT6, sinT6, _dh.D6, 0, 1, 0).InverseRigid() * Affine.Dh(turned.CosT5, sinT5, _dh.D5, 0, 0, -1).InverseRigid();
        double x = t14.Px, y = t14.Py;
        double c3 = (x * x + y * y - a2 * a2 - a3 * a3) / (2 * a2 * a3);
        if (c3 > 1 + 1e-12 || c3 < -1 - 1e-12)
        {
            elbows = default;
            return false;
        }
        double t3Abs = Math.Acos(Math.Clamp(c3, -1, 1));
        (double sinT3Abs, double cosT3) = Math.SinCos(t3Abs);
        // The same for both elbows; the elbow's angle at +θ3 (at −θ3 it is its negative).
        elbows = new Elbows(t5, t6, t3Abs, Math.Atan2(y, x), Math.Atan2(t14.R10, t14.R00), Math.Atan2(a3 * sinT3Abs, a2 + a3 * cosT3));
        return true;
    }

    private static Joints SolutionOf(in Shoulder arm, in Elbows e, int elbow)
    {
        double t3 = elbow == 0 ? -e.T3Abs : e.T3Abs;
        double t2 = e.TowardsWrist - (elbow == 0 ? -e.Bend : e.Bend);
        double t4 = e.Arm234 - t2 - t3;
        return new Joints(
            KinematicsCore.WrapDegrees(arm.T1), KinematicsCore.WrapDegrees(t2), KinematicsCore.WrapDegrees(t3),
            KinematicsCore.WrapDegrees(t4), KinematicsCore.WrapDegrees(e.T5), KinematicsCore.WrapDegrees(e.T6));
    }
}
