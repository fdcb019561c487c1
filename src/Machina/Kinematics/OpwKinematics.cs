namespace Machina;

/// <summary>
/// Kinematics of ortho-parallel arms with a spherical wrist (ABB and KUKA six-axis arms), with an analytical inverse that
/// returns all eight solutions. Joint values follow the brand's own conventions (see docs/kinematics.md).
/// </summary>
public sealed class OpwKinematics : IKinematics, ISolver
{
    private readonly OpwParameters _p;
    private readonly bool _kuka;
    private readonly double _e, _k, _psi;

    internal OpwKinematics(RobotModel model, OpwParameters parameters, bool kukaConvention)
    {
        Model = model;
        _p = parameters;
        _kuka = kukaConvention;
        _e = -parameters.A2;
        _k = Math.Sqrt(parameters.C3 * parameters.C3 + _e * _e);
        _psi = Math.Atan2(_e, parameters.C3);
    }

    /// <inheritdoc/>
    public RobotModel Model { get; }

    /// <summary>The OPW lengths of this arm, in mm.</summary>
    public OpwParameters Parameters => _p;

    // Canonical angles (radians): axis 1 about +Z, axes 2 and 3 about +Y (positive tilts forward/down), axes 4 and 6 about the
    // forearm (+X), axis 5 about +Y; all zero = lower arm vertical, forearm horizontal forward. That is exactly ABB's convention.
    private void ToCanonical(Joints j, Span<double> t)
    {
        if (_kuka)
        {
            t[0] = -j.J1; t[1] = j.J2 + 90; t[2] = j.J3 - 90; t[3] = -j.J4; t[4] = j.J5; t[5] = -j.J6;
        }
        else
        {
            t[0] = j.J1; t[1] = j.J2; t[2] = j.J3; t[3] = j.J4; t[4] = j.J5; t[5] = j.J6;
        }
        for (int i = 0; i < 6; i++)
        {
            t[i] *= Angles.ToRadians;
        }
    }

    private Joints FromCanonical(double t1, double t2, double t3, double t4, double t5, double t6)
    {
        double a1 = KinematicsCore.WrapDegrees(t1), a2 = KinematicsCore.WrapDegrees(t2), a3 = KinematicsCore.WrapDegrees(t3);
        double a4 = KinematicsCore.WrapDegrees(t4), a5 = KinematicsCore.WrapDegrees(t5), a6 = KinematicsCore.WrapDegrees(t6);
        if (!_kuka)
        {
            return new Joints(a1, a2, a3, a4, a5, a6);
        }
        return new Joints(Neg(a1), Wrap(a2 - 90), Wrap(a3 + 90), Neg(a4), a5, Neg(a6));

        static double Neg(double d) => d == -180 || d == 180 ? 180 : -d;
        static double Wrap(double d) => d > 180 ? d - 360 : d <= -180 ? d + 360 : d;
    }

    /// <summary>Wrist rotation (canonical: X along the forearm/tool axis) from the flange rotation, per brand.</summary>
    private Affine WristFromFlange(in Affine f) =>
        // ABB tool0 and KUKA FLANGE are both the wrist frame turned +90° about Y: Z out of the flange, X down at the home pose.
        new(f.R02, f.R01, -f.R00, f.R12, f.R11, -f.R10, f.R22, f.R21, -f.R20, f.Px, f.Py, f.Pz);

    private Affine FlangeFromWrist(in Affine w) =>
        new(-w.R02, w.R01, w.R00, -w.R12, w.R11, w.R10, -w.R22, w.R21, w.R20, w.Px, w.Py, w.Pz);

    /// <inheritdoc/>
    public Pose Forward(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        Span<double> t = stackalloc double[6];
        ToCanonical(joints, t);
        return FlangeFromWrist(ForwardCanonical(t)).ToPose();
    }

    /// <summary>Where the arm's joints are for these joint values: base, axis 1 at shoulder height, shoulder, elbow, the forearm's offset, wrist centre, flange.</summary>
    internal Vector[] LinkPoints(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        Span<double> t = stackalloc double[6];
        ToCanonical(joints, t);
        double c1 = Math.Cos(t[0]), s1 = Math.Sin(t[0]), phi = t[1] + t[2];
        Vector At(double reach, double z) => new(reach * c1 - _p.B * s1, reach * s1 + _p.B * c1, z);
        double elbowReach = _p.A1 + _p.C2 * Math.Sin(t[1]), elbowZ = _p.C1 + _p.C2 * Math.Cos(t[1]);
        double offsetReach = elbowReach + _e * Math.Sin(phi), offsetZ = elbowZ + _e * Math.Cos(phi);
        return
        [
            Vector.Zero,
            new Vector(0, 0, _p.C1),
            At(_p.A1, _p.C1),
            At(elbowReach, elbowZ),
            At(offsetReach, offsetZ),
            At(offsetReach + _p.C3 * Math.Cos(phi), offsetZ - _p.C3 * Math.Sin(phi)),
            Forward(joints).Position,
        ];
    }

    /// <summary>Horizontal distance of the wrist centre in front of axis 1 (in the axis-1 frame; negative = behind).</summary>
    private double Reach(ReadOnlySpan<double> t)
    {
        double phi = t[1] + t[2];
        return _p.A1 + _p.C2 * Math.Sin(t[1]) + _p.C3 * Math.Cos(phi) + _e * Math.Sin(phi);
    }

    private Affine ForwardCanonical(ReadOnlySpan<double> t)
    {
        double phi = t[1] + t[2];
        double s = Reach(t);
        double z = _p.C1 + _p.C2 * Math.Cos(t[1]) - _p.C3 * Math.Sin(phi) + _e * Math.Cos(phi);
        // Math.SinCos gives Math.Sin's and Math.Cos's bits (MathSinCosTests), in one call.
        (double s1, double c1) = Math.SinCos(t[0]);
        (double sPhi, double cPhi) = Math.SinCos(phi);
        (double s4, double c4) = Math.SinCos(t[3]);
        (double s5, double c5) = Math.SinCos(t[4]);
        (double s6, double c6) = Math.SinCos(t[5]);
        Affine r = Affine.RotZ(c1, s1) * Affine.RotY(cPhi, sPhi) * Affine.RotX(c4, s4) * Affine.RotY(c5, s5) * Affine.RotX(c6, s6);
        double wx = s * c1 - _p.B * s1, wy = s * s1 + _p.B * c1;
        return r.WithTranslation(wx + _p.C4 * r.R00, wy + _p.C4 * r.R10, z + _p.C4 * r.R20);
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
    public ArmConfiguration ConfigurationOf(Joints joints)
    {
        Span<double> t = stackalloc double[6];
        ToCanonical(joints, t);
        double s = Reach(t);
        return new ArmConfiguration(s < 0, Math.Cos(t[2] - _psi) < 0, Math.Sin(t[4]) < 0);
    }

    SingularityMeasure ISolver.Measure(Joints joints)
    {
        Span<double> t = stackalloc double[6];
        ToCanonical(joints, t);
        double s = Reach(t);
        double wrist = Math.Asin(Math.Min(1, Math.Abs(Math.Sin(t[4])))) * Angles.ToDegrees;
        double elbow = Math.Asin(Math.Min(1, Math.Abs(Math.Cos(t[2] - _psi)))) * Angles.ToDegrees;
        return new SingularityMeasure(wrist, elbow, Math.Abs(s));
    }

    int ISolver.SolveRaw(in Affine flange, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations)
    {
        Span<double> r = stackalloc double[6];
        ToCanonical(reference, r);
        double r4 = r[3], r6 = r[5];
        Affine w = WristFromFlange(flange);
        double cx = w.Px - _p.C4 * w.R00, cy = w.Py - _p.C4 * w.R10, cz = w.Pz - _p.C4 * w.R20;
        double rho2 = cx * cx + cy * cy - _p.B * _p.B;
        if (rho2 < 0 || !double.IsFinite(rho2))
        {
            return 0;
        }
        double sFront = Math.Sqrt(rho2);
        // Wrist centre on axis 1 (shoulder singularity, b = 0): axis 1 is free and atan2 would only see rounding noise; keep the reference's.
        double baseAngle = cx * cx + cy * cy < 1e-18 ? r[0] : Math.Atan2(cy, cx);
        double c2 = _p.C2, k = _k;
        int count = 0;
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            double s = shoulder == 0 ? sFront : -sFront;
            double t1 = baseAngle - Math.Atan2(_p.B, s);
            double u = s - _p.A1, v = cz - _p.C1;
            double d = (u * u + v * v - c2 * c2 - k * k) / (2 * c2 * k);
            if (d > 1 + 1e-12 || d < -1 - 1e-12)
            {
                continue;
            }
            double asinD = Math.Asin(Math.Clamp(d, -1, 1));
            (double s1, double c1) = Math.SinCos(t1); // the bits of Math.Sin and Math.Cos (MathSinCosTests), in one call
            // Wrist rotation in the axis-1 frame (Rz(−θ1)·W), reused for both elbows.
            double m00 = c1 * w.R00 + s1 * w.R10, m01 = c1 * w.R01 + s1 * w.R11, m02 = c1 * w.R02 + s1 * w.R12;
            double m10 = -s1 * w.R00 + c1 * w.R10, m11 = -s1 * w.R01 + c1 * w.R11, m12 = -s1 * w.R02 + c1 * w.R12;
            double m20 = w.R20, m21 = w.R21, m22 = w.R22;
            for (int elbow = 0; elbow < 2; elbow++)
            {
                double t3 = elbow == 0 ? _psi - asinD : _psi - Math.PI + asinD;
                double g = t3 - _psi;
                (double sinG, double cosG) = Math.SinCos(g);
                double a = c2 - k * sinG, b = k * cosG;
                double t2 = Math.Atan2(a * u - b * v, a * v + b * u);
                double phi = t2 + t3;
                (double sp, double cp) = Math.SinCos(phi);
                // M = Ry(−φ)·Rz(−θ1)·W = Rx(θ4)·Ry(θ5)·Rx(θ6)
                double n00 = cp * m00 - sp * m20;
                double n10 = m10, n11 = m11, n12 = m12;
                double n20 = sp * m00 + cp * m20, n21 = sp * m01 + cp * m21, n22 = sp * m02 + cp * m22;
                double s5 = Math.Sqrt(n10 * n10 + n20 * n20);
                double t5 = Math.Atan2(s5, n00);
                // Near a straight wrist θ4 alone is ill-conditioned; θ6 is then taken from what θ4 and θ5 leave,
                // Rx(θ6) = Ry(−θ5)·Rx(−θ4)·M, so the pair always reproduces the rotation (row 1 does not depend on θ5).
                bool straight = s5 <= 1e-12;
                double t4 = straight ? r4 : Math.Atan2(n10, -n20);
                (double s4, double c4) = Math.SinCos(t4);
                double t6 = Math.Atan2(-(c4 * n12 + s4 * n22), c4 * n11 + s4 * n21);
                if (straight)
                {
                    // Only θ4 + θ6 (θ5 = 0) or θ6 − θ4 (θ5 = 180°) is fixed: share the change from the reference equally between the two axes.
                    double half = Math.IEEERemainder(t6 - r6, 2 * Math.PI) / 2;
                    t4 += n00 > 0 ? half : -half;
                    t6 -= half;
                }
                bool back = shoulder == 1, down = elbow == 1;
                joints[count] = FromCanonical(t1, t2, t3, t4, t5, t6);
                configurations[count++] = new ArmConfiguration(back, down, false);
                joints[count] = FromCanonical(t1, t2, t3, t4 + Math.PI, -t5, t6 + Math.PI);
                configurations[count++] = new ArmConfiguration(back, down, true);
            }
        }
        return count;
    }
}
