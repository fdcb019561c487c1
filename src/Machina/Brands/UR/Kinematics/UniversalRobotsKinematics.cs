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
        double d1 = _dh.D1, a2 = _dh.A2, a3 = _dh.A3, d4 = _dh.D4, d5 = _dh.D5, d6 = _dh.D6;
        double px = t.Px - d6 * t.R02, py = t.Py - d6 * t.R12;
        double r = Math.Sqrt(px * px + py * py);
        if (!(r >= Math.Abs(d4) - 1e-9) || r == 0)
        {
            return 0;
        }
        double phi1 = Math.Atan2(py, px), phi2 = Math.Acos(Math.Clamp(d4 / r, -1, 1));
        int count = 0;
        // Each sine and cosine below is taken once: Math.SinCos gives Math.Sin's and Math.Cos's bits, and the solutions that differ
        // only in the sign of an angle (θ5 of the two wrists, θ3 of the two elbows) take sin(−x) = −sin(x), cos(−x) = cos(x) and
        // atan2(−y, x) = −atan2(y, x), which hold to the bit (UniversalRobotsSolveBitsTests compares with the full computation).
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            double t1 = phi1 + (shoulder == 0 ? phi2 : -phi2) + HalfPi;
            (double s1, double c1) = Math.SinCos(t1);
            // T01⁻¹ · T, the same for both wrists.
            Affine t1t = Affine.Dh(c1, s1, d1, 0, 0, 1).InverseRigid() * t;
            // The unit vector (s1, −c1, 0) seen from the flange is (s5·cos θ6, −s5·sin θ6, cos θ5). Taking θ5 with atan2 from it (rather
            // than acos of the flange position, which equals cos θ5 exactly) keeps full precision near the straight wrist θ5 = 0.
            double ux = t.R00 * s1 - t.R10 * c1, uy = t.R01 * s1 - t.R11 * c1, c5 = t.R02 * s1 - t.R12 * c1;
            double s5Abs = Math.Sqrt(ux * ux + uy * uy);
            double t5Abs = Math.Atan2(s5Abs, c5);
            (double sinT5Abs, double cosT5) = Math.SinCos(t5Abs);
            for (int wrist = 0; wrist < 2; wrist++)
            {
                double t5 = wrist == 0 ? t5Abs : -t5Abs;
                double sinT5 = wrist == 0 ? sinT5Abs : -sinT5Abs;
                double sign = wrist == 0 ? 1 : -1;
                // Straight wrist: θ6 is free (axes 2, 3 and 4 make up for it); keep the reference's.
                double t6 = s5Abs < 1e-12 ? reference.J6 * Angles.ToRadians : Math.Atan2(-uy * sign, ux * sign);
                (double sinT6, double cosT6) = Math.SinCos(t6);
                // Frame 1 → 4: T14 = T01⁻¹ · T · T56⁻¹ · T45⁻¹
                Affine t14 = t1t * Affine.Dh(cosT6, sinT6, d6, 0, 1, 0).InverseRigid() * Affine.Dh(cosT5, sinT5, d5, 0, 0, -1).InverseRigid();
                double x = t14.Px, y = t14.Py;
                double c3 = (x * x + y * y - a2 * a2 - a3 * a3) / (2 * a2 * a3);
                if (c3 > 1 + 1e-12 || c3 < -1 - 1e-12)
                {
                    continue;
                }
                double t3Abs = Math.Acos(Math.Clamp(c3, -1, 1));
                // The same for both elbows.
                double towardsWrist = Math.Atan2(y, x), arm234 = Math.Atan2(t14.R10, t14.R00);
                (double sinT3Abs, double cosT3) = Math.SinCos(t3Abs);
                // The elbow's angle at +θ3; at −θ3 it is its negative.
                double bend = Math.Atan2(a3 * sinT3Abs, a2 + a3 * cosT3);
                for (int elbow = 0; elbow < 2; elbow++)
                {
                    double t3 = elbow == 0 ? -t3Abs : t3Abs;
                    double t2 = towardsWrist - (elbow == 0 ? -bend : bend);
                    double t4 = arm234 - t2 - t3;
                    joints[count] = new Joints(
                        KinematicsCore.WrapDegrees(t1), KinematicsCore.WrapDegrees(t2), KinematicsCore.WrapDegrees(t3),
                        KinematicsCore.WrapDegrees(t4), KinematicsCore.WrapDegrees(t5), KinematicsCore.WrapDegrees(t6));
                    configurations[count++] = new ArmConfiguration(shoulder == 1, elbow == 1, wrist == 1);
                }
            }
        }
        return count;
    }
}
