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
        _bZero = BitConverter.DoubleToInt64Bits(parameters.B) == 0;
    }

    /// <summary>
    /// b (the forearm's sideways offset) is +0, as on every catalogue arm: axis 1's offset angle atan2(b, ±ρ) is then +0 in front
    /// (ρ ≥ +0) and π behind (−ρ, −0 included), which is what atan2 gives there to the bit (<c>OpwShoulderAngleTests</c>).
    /// </summary>
    private readonly bool _bZero;

    /// <inheritdoc/>
    public RobotModel Model { get; }

    /// <summary>The OPW lengths of this arm, in mm.</summary>
    public OpwParameters Parameters => _p;

    // Canonical angles (radians): axis 1 about +Z, axes 2 and 3 about +Y (positive tilts forward/down), axes 4 and 6 about the
    // forearm (+X), axis 5 about +Y; all zero = lower arm vertical, forearm horizontal forward. That is exactly ABB's convention.
    private Canonical ToCanonical(Joints j) => _kuka
        ? new Canonical(-j.J1 * Angles.ToRadians, (j.J2 + 90) * Angles.ToRadians, (j.J3 - 90) * Angles.ToRadians,
            -j.J4 * Angles.ToRadians, j.J5 * Angles.ToRadians, -j.J6 * Angles.ToRadians)
        : new Canonical(j.J1 * Angles.ToRadians, j.J2 * Angles.ToRadians, j.J3 * Angles.ToRadians,
            j.J4 * Angles.ToRadians, j.J5 * Angles.ToRadians, j.J6 * Angles.ToRadians);

    /// <summary>The six canonical angles (radians) of a joint set.</summary>
    private readonly record struct Canonical(double T1, double T2, double T3, double T4, double T5, double T6);

    private Joints FromCanonical(in Canonical t)
    {
        double a1 = KinematicsCore.WrapDegrees(t.T1), a2 = KinematicsCore.WrapDegrees(t.T2), a3 = KinematicsCore.WrapDegrees(t.T3);
        double a4 = KinematicsCore.WrapDegrees(t.T4), a5 = KinematicsCore.WrapDegrees(t.T5), a6 = KinematicsCore.WrapDegrees(t.T6);
        if (!_kuka)
        {
            return new Joints(a1, a2, a3, a4, a5, a6);
        }
        return new Joints(Neg(a1), Wrap(a2 - 90), Wrap(a3 + 90), Neg(a4), a5, Neg(a6));
    }

    /// <summary>Axis 1 in the brand's degrees, as <see cref="FromCanonical"/> gives it.</summary>
    private double BrandJ1(double t1)
    {
        double a1 = KinematicsCore.WrapDegrees(t1);
        return _kuka ? Neg(a1) : a1;
    }

    /// <summary>Axis 3 in the brand's degrees, as <see cref="FromCanonical"/> gives it.</summary>
    private double BrandJ3(double t3)
    {
        double a3 = KinematicsCore.WrapDegrees(t3);
        return _kuka ? Wrap(a3 + 90) : a3;
    }

    /// <summary>Axis 4 in the brand's degrees, as <see cref="FromCanonical"/> gives it.</summary>
    private double BrandJ4(double t4)
    {
        double a4 = KinematicsCore.WrapDegrees(t4);
        return _kuka ? Neg(a4) : a4;
    }

    private static double Neg(double d) => d == -180 || d == 180 ? 180 : -d;

    private static double Wrap(double d) => d > 180 ? d - 360 : d <= -180 ? d + 360 : d;

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
        return FlangeFromWrist(ForwardCanonical(ToCanonical(joints))).ToPose();
    }

    /// <summary>Where the arm's joints are for these joint values: base, axis 1 at shoulder height, shoulder, elbow, the forearm's offset, wrist centre, flange.</summary>
    internal Vector[] LinkPoints(Joints joints)
    {
        joints.RequireFinite(nameof(joints));
        Canonical t = ToCanonical(joints);
        double c1 = Math.Cos(t.T1), s1 = Math.Sin(t.T1), phi = t.T2 + t.T3;
        Vector At(double reach, double z) => new(reach * c1 - _p.B * s1, reach * s1 + _p.B * c1, z);
        double elbowReach = _p.A1 + _p.C2 * Math.Sin(t.T2), elbowZ = _p.C1 + _p.C2 * Math.Cos(t.T2);
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

    /// <summary>
    /// Horizontal distance of the wrist centre in front of axis 1 (in the axis-1 frame; negative = behind), from sin θ2 and the cosine
    /// and sine of φ = θ2 + θ3.
    /// </summary>
    private double Reach(double sinT2, double cosPhi, double sinPhi) => _p.A1 + _p.C2 * sinT2 + _p.C3 * cosPhi + _e * sinPhi;

    /// <summary><see cref="Reach(double, double, double)"/> of a joint set's canonical angles.</summary>
    private double Reach(in Canonical t)
    {
        // Math.SinCos gives Math.Sin's and Math.Cos's bits (MathSinCosTests), in one call.
        (double sPhi, double cPhi) = Math.SinCos(t.T2 + t.T3);
        return Reach(Math.Sin(t.T2), cPhi, sPhi);
    }

    private Affine ForwardCanonical(in Canonical t)
    {
        // Math.SinCos gives Math.Sin's and Math.Cos's bits (MathSinCosTests), in one call.
        (double s2, double c2) = Math.SinCos(t.T2);
        (double sPhi, double cPhi) = Math.SinCos(t.T2 + t.T3);
        double s = Reach(s2, cPhi, sPhi);
        double z = _p.C1 + _p.C2 * c2 - _p.C3 * sPhi + _e * cPhi;
        (double s1, double c1) = Math.SinCos(t.T1);
        (double s4, double c4) = Math.SinCos(t.T4);
        (double s5, double c5) = Math.SinCos(t.T5);
        (double s6, double c6) = Math.SinCos(t.T6);
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
        Canonical t = ToCanonical(joints);
        return new ArmConfiguration(Reach(t) < 0, Math.Cos(t.T3 - _psi) < 0, Math.Sin(t.T5) < 0);
    }

    SingularityMeasure ISolver.Measure(Joints joints)
    {
        Canonical t = ToCanonical(joints);
        return MeasureOf(Math.Sin(t.T5), Math.Cos(t.T3 - _psi), Reach(t));
    }

    /// <remarks>What <see cref="ConfigurationOf"/> and <c>Measure</c> give, from one sine of axis 5, one cosine of the elbow and one reach.</remarks>
    (ArmConfiguration Configuration, SingularityMeasure Measure) ISolver.Assess(Joints joints)
    {
        Canonical t = ToCanonical(joints);
        double sin5 = Math.Sin(t.T5), cosElbow = Math.Cos(t.T3 - _psi), s = Reach(t);
        return (new ArmConfiguration(s < 0, cosElbow < 0, sin5 < 0), MeasureOf(sin5, cosElbow, s));
    }

    /// <summary>The singularity measure from sin θ5, the elbow's cos(θ3 − ψ) and the wrist centre's reach.</summary>
    private static SingularityMeasure MeasureOf(double sin5, double cosElbow, double reach) => new(
        Math.Asin(Math.Min(1, Math.Abs(sin5))) * Angles.ToDegrees, Math.Asin(Math.Min(1, Math.Abs(cosElbow))) * Angles.ToDegrees, Math.Abs(reach));

    int ISolver.SolveRaw(in Affine flange, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations)
    {
        if (!TryWrist(flange, reference, out Wrist wrist))
        {
            return 0;
        }
        int count = 0;
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            if (!TryShoulder(wrist, shoulder, out Shoulder arm))
            {
                continue;
            }
            Frame frame = FrameOf(wrist, arm);
            for (int elbow = 0; elbow < 2; elbow++)
            {
                Branch(wrist, arm, frame, elbow, out Canonical first);
                joints[count] = FromCanonical(first);
                joints[count + 1] = FromCanonical(Flipped(first));
                configurations[count++] = new ArmConfiguration(shoulder == 1, elbow == 1, false);
                configurations[count++] = new ArmConfiguration(shoulder == 1, elbow == 1, true);
            }
        }
        return count;
    }

    /// <remarks>
    /// The same solution as <see cref="KinematicsCore.ClosestOf"/> of <c>SolveRaw</c>, to the bit, without solving every branch: each of
    /// the four arm branches (shoulder, elbow) first gets its axis 1 and axis 3 (one arc tangent per shoulder, no more), which give a
    /// lower bound of the cost of both its wrist solutions (a joint's change is at least its distance to the reference modulo 360°);
    /// the branch with the lowest bound is solved first, and another only when its bound does not exceed the best cost found. The
    /// choice is then made over the solved ones in <c>SolveRaw</c>'s order with the same strict comparison, so ties go where they went.
    /// </remarks>
    Joints? ISolver.Closest(in Affine flange, in Joints reference, out bool reachable)
    {
        reachable = false;
        if (!TryWrist(flange, reference, out Wrist wrist))
        {
            return null;
        }
        Span<Shoulder> arms = stackalloc Shoulder[2];
        Span<bool> armOk = stackalloc bool[2];
        Span<double> bound = stackalloc double[4];
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            armOk[shoulder] = TryShoulder(wrist, shoulder, out arms[shoulder]);
            reachable |= armOk[shoulder];
            // Axis 1 is the same for both elbows of a shoulder: its distance is taken once.
            double axis1 = armOk[shoulder] ? KinematicsCore.TurnDistance(BrandJ1(arms[shoulder].T1), reference.J1) : 0;
            for (int elbow = 0; elbow < 2; elbow++)
            {
                double b = armOk[shoulder]
                    ? Math.Max(axis1, KinematicsCore.TurnDistance(BrandJ3(ElbowAngle(arms[shoulder], elbow)), reference.J3))
                    : double.PositiveInfinity;
                // A bound that is not a number proves nothing: that branch is solved first.
                bound[shoulder * 2 + elbow] = double.IsNaN(b) ? double.NegativeInfinity : b;
            }
        }
        if (!reachable)
        {
            return null;
        }
        // Fitted solutions by SolveRaw's order (shoulder, elbow, wrist); cost +∞ where not solved or beyond the limits.
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
            Shoulder arm = arms[next >> 1];
            Branch(wrist, arm, FrameOf(wrist, arm), next & 1, out Canonical first);
            best = Math.Min(best, Fit(first, reference, best, out fitted[next * 2], out cost[next * 2]));
            best = Math.Min(best, Fit(Flipped(first), reference, best, out fitted[next * 2 + 1], out cost[next * 2 + 1]));
        }
        return KinematicsCore.Lowest(cost, fitted);

        // A wrist solution whose axis 4 alone is farther from the reference than the best cost found (a LIN's flipped wrist, half a
        // turn away) cannot be the closest: it is neither converted nor fitted, and keeps cost +∞ (its cost would be at least that
        // distance, less the clamp's 1e-9°: the bound's margin covers it, as for the branches).
        double Fit(in Canonical raw, in Joints current, double bestSoFar, out Joints f, out double c)
        {
            if (bestSoFar < double.PositiveInfinity && KinematicsCore.TurnDistance(BrandJ4(raw.T4), current.J4) - KinematicsCore.BoundMargin > bestSoFar)
            {
                f = default;
                c = double.PositiveInfinity;
                return c;
            }
            c = KinematicsCore.FitLimits(Model, FromCanonical(raw), current, out f) ? KinematicsCore.Cost(f, current) : double.PositiveInfinity;
            return c;
        }
    }

    /// <summary>The wrist's target and what every branch shares: the wrist centre, its distance from axis 1, the reference's axes 1, 4, 6.</summary>
    private readonly record struct Wrist(Affine W, double Cz, double SFront, double BaseAngle, double R4, double R6);

    /// <summary>One shoulder's axis 1 and what both its elbows share.</summary>
    private readonly record struct Shoulder(double T1, double U, double V, double AsinD);

    /// <summary>The wrist rotation in the axis-1 frame (Rz(−θ1)·W), shared by a shoulder's two elbows.</summary>
    private readonly record struct Frame(double M00, double M01, double M02, double M10, double M11, double M12, double M20, double M21, double M22);

    private bool TryWrist(in Affine flange, in Joints reference, out Wrist wrist)
    {
        Canonical r = ToCanonical(reference);
        Affine w = WristFromFlange(flange);
        double cx = w.Px - _p.C4 * w.R00, cy = w.Py - _p.C4 * w.R10, cz = w.Pz - _p.C4 * w.R20;
        double rho2 = cx * cx + cy * cy - _p.B * _p.B;
        if (rho2 < 0 || !double.IsFinite(rho2))
        {
            wrist = default;
            return false;
        }
        // Wrist centre on axis 1 (shoulder singularity, b = 0): axis 1 is free and atan2 would only see rounding noise; keep the reference's.
        double baseAngle = cx * cx + cy * cy < 1e-18 ? r.T1 : Math.Atan2(cy, cx);
        wrist = new Wrist(w, cz, Math.Sqrt(rho2), baseAngle, r.T4, r.T6);
        return true;
    }

    private bool TryShoulder(in Wrist wrist, int shoulder, out Shoulder arm)
    {
        double c2 = _p.C2, k = _k;
        double s = shoulder == 0 ? wrist.SFront : -wrist.SFront;
        double t1 = wrist.BaseAngle - (_bZero ? (double.IsNegative(s) ? Math.PI : 0.0) : Math.Atan2(_p.B, s));
        double u = s - _p.A1, v = wrist.Cz - _p.C1;
        double d = (u * u + v * v - c2 * c2 - k * k) / (2 * c2 * k);
        if (d > 1 + 1e-12 || d < -1 - 1e-12)
        {
            arm = default;
            return false;
        }
        arm = new Shoulder(t1, u, v, Math.Asin(Math.Clamp(d, -1, 1)));
        return true;
    }

    private static Frame FrameOf(in Wrist wrist, in Shoulder arm)
    {
        Affine w = wrist.W;
        (double s1, double c1) = Math.SinCos(arm.T1); // the bits of Math.Sin and Math.Cos (MathSinCosTests), in one call
        return new Frame(
            c1 * w.R00 + s1 * w.R10, c1 * w.R01 + s1 * w.R11, c1 * w.R02 + s1 * w.R12,
            -s1 * w.R00 + c1 * w.R10, -s1 * w.R01 + c1 * w.R11, -s1 * w.R02 + c1 * w.R12,
            w.R20, w.R21, w.R22);
    }

    /// <summary>Axis 3 (canonical radians) of one elbow.</summary>
    private double ElbowAngle(in Shoulder arm, int elbow) => elbow == 0 ? _psi - arm.AsinD : _psi - Math.PI + arm.AsinD;

    /// <summary>One arm branch's first wrist solution (canonical radians, not wrapped); the other is <see cref="Flipped"/> of it.</summary>
    private void Branch(in Wrist wrist, in Shoulder arm, in Frame m, int elbow, out Canonical first)
    {
        double c2 = _p.C2, k = _k, u = arm.U, v = arm.V, t1 = arm.T1;
        double t3 = ElbowAngle(arm, elbow);
        double g = t3 - _psi;
        (double sinG, double cosG) = Math.SinCos(g);
        double a = c2 - k * sinG, b = k * cosG;
        double t2 = Math.Atan2(a * u - b * v, a * v + b * u);
        double phi = t2 + t3;
        (double sp, double cp) = Math.SinCos(phi);
        // M = Ry(−φ)·Rz(−θ1)·W = Rx(θ4)·Ry(θ5)·Rx(θ6)
        double n00 = cp * m.M00 - sp * m.M20;
        double n10 = m.M10, n11 = m.M11, n12 = m.M12;
        double n20 = sp * m.M00 + cp * m.M20, n21 = sp * m.M01 + cp * m.M21, n22 = sp * m.M02 + cp * m.M22;
        double s5 = Math.Sqrt(n10 * n10 + n20 * n20);
        double t5 = Math.Atan2(s5, n00);
        // Near a straight wrist θ4 alone is ill-conditioned; θ6 is then taken from what θ4 and θ5 leave,
        // Rx(θ6) = Ry(−θ5)·Rx(−θ4)·M, so the pair always reproduces the rotation (row 1 does not depend on θ5).
        bool straight = s5 <= 1e-12;
        double t4 = straight ? wrist.R4 : Math.Atan2(n10, -n20);
        (double s4, double c4) = Math.SinCos(t4);
        double t6 = Math.Atan2(-(c4 * n12 + s4 * n22), c4 * n11 + s4 * n21);
        if (straight)
        {
            // Only θ4 + θ6 (θ5 = 0) or θ6 − θ4 (θ5 = 180°) is fixed: share the change from the reference equally between the two axes.
            double half = Math.IEEERemainder(t6 - wrist.R6, 2 * Math.PI) / 2;
            t4 += n00 > 0 ? half : -half;
            t6 -= half;
        }
        first = new Canonical(t1, t2, t3, t4, t5, t6);
    }

    /// <summary>A branch's other wrist solution: axes 4 and 6 half a turn on, axis 5 mirrored.</summary>
    private static Canonical Flipped(in Canonical first) => new(first.T1, first.T2, first.T3, first.T4 + Math.PI, -first.T5, first.T6 + Math.PI);
}
