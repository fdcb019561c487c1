namespace Machina.Tests.Kinematics;

/// <summary>
/// The ortho-parallel solver's closest solution solves only the arm branches that could be closest (a lower bound from axes 1 and 3):
/// it must be the solution <see cref="KinematicsCore.ClosestOf"/> picks from all eight raw solutions, to the last bit, on every
/// ortho-parallel arm, for references next to the target (a streamed move), anywhere, in another configuration, and near the straight
/// wrist, the stretched elbow and axis 1's singular line; and it must say "out of reach" exactly when there is no raw solution.
/// </summary>
public class OpwClosestTests
{
    public static TheoryData<string> OpwModels()
    {
        var data = new TheoryData<string>();
        foreach (RobotModel model in RobotModels.All)
        {
            if (model.Kinematics is OpwKinematics)
            {
                data.Add(model.Name);
            }
        }
        return data;
    }

    [Fact]
    public void TheCatalogueHasOrthoParallelArmsOfBothBrands()
    {
        Assert.Contains(RobotModels.All, m => m.Kinematics is OpwKinematics && m.Brand == "ABB");
        Assert.Contains(RobotModels.All, m => m.Kinematics is OpwKinematics && m.Brand == "KUKA");
    }

    [Theory]
    [MemberData(nameof(OpwModels))]
    public void Closest_IsClosestOfEveryRawSolution_BitForBit(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (OpwKinematics)model.Kinematics;
        var solver = (ISolver)kin;
        var random = new Random(4549);
        int found = 0, unreachable = 0, beyondLimits = 0;
        for (int i = 0; i < 6000; i++)
        {
            Joints j = (i % 6) switch
            {
                0 => Random(random),
                1 => Random(random) with { J5 = Near(random, 0) },                                   // wrist nearly straight
                2 => Random(random) with { J5 = 0 },                                                 // wrist exactly straight
                3 => Random(random) with { J3 = Near(random, random.Next(2) == 0 ? 0 : 180) },       // near the elbow's extremes
                4 => Within(model, random),
                _ => Within(model, random) with { J4 = Near(random, 0), J5 = Near(random, 0) },
            };
            Pose pose = kin.Forward(j);
            if (i % 50 == 7)
            {
                pose = new Pose(pose.Position * 3, pose.Rotation);                                   // out of reach
            }
            Affine flange = Affine.FromPose(pose);
            Joints reference = (i % 4) switch
            {
                0 => Nudged(j, random, 0.5),                                                         // the streamed case: just before
                1 => Random(random),
                2 => Nudged(j, random, 0.5) with { J1 = j.J1 + 180 },                                // the other shoulder's side
                _ => Nudged(j, random, 1e-9),
            };
            Joints? got = solver.Closest(flange, reference, out bool reachable);
            Joints? want = KinematicsCore.ClosestOfAll(solver, model, flange, reference, out bool wantReachable);
            Assert.Equal(wantReachable, reachable);
            Assert.True(want is null ? got is null : got is Joints g && SameBits.Of(want.Value, g), $"{name}, pose of {j} from {reference}: {got} instead of {want}");
            found += got is null ? 0 : 1;
            unreachable += reachable ? 0 : 1;
            beyondLimits += reachable && got is null ? 1 : 0;
        }
        Assert.True(found > 3000, $"only {found} solutions: the comparison saw too few");
        Assert.True(unreachable >= 80, $"only {unreachable} unreachable poses");
        Assert.True(beyondLimits > 0, "no pose had every solution beyond the limits");
    }

    [Theory]
    [MemberData(nameof(OpwModels))]
    public void Closest_FromEitherWrist_IsClosestOfEveryRawSolution_BitForBit(string name)
    {
        // A wrist solution whose axis 4 alone is farther from the reference than the best cost found is skipped (session 35): from
        // references at each raw solution, at its flipped wrist (axes 4 and 6 half a turn on, axis 5 mirrored) and with axis 4 a few
        // degrees either side of that half turn, the answer is still the full search's, and both wrists get chosen.
        RobotModel model = RobotModels.Get(name);
        var kin = (OpwKinematics)model.Kinematics;
        var solver = (ISolver)kin;
        var random = new Random(3555);
        Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> configurations = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        int compared = 0, flippedChosen = 0;
        for (int i = 0; i < 400; i++)
        {
            Joints j = i % 4 == 1 ? Within(model, random) with { J5 = Near(random, 0) } : Within(model, random);
            Affine flange = Affine.FromPose(kin.Forward(j));
            int n = solver.SolveRaw(flange, j, raw, configurations);
            for (int s = 0; s < n; s++)
            {
                Joints at = raw[s];
                Joints flipped = at with { J4 = at.J4 + 180, J5 = -at.J5, J6 = at.J6 + 180 };
                foreach (Joints reference in new[]
                {
                    Nudged(at, random, 0.5), Nudged(flipped, random, 0.5), at with { J4 = at.J4 + 180 + Step(random, 3) },
                    at with { J4 = at.J4 + 90 + Step(random, 1e-7) }, Nudged(at, random, 0.5) with { J4 = at.J4 - 180 },
                })
                {
                    Joints? got = solver.Closest(flange, reference, out bool reachable);
                    Joints? want = KinematicsCore.ClosestOfAll(solver, model, flange, reference, out bool wantReachable);
                    Assert.Equal(wantReachable, reachable);
                    Assert.True(want is null ? got is null : got is Joints g && SameBits.Of(want.Value, g), $"{name}, pose of {j} from {reference}: {got} instead of {want}");
                    compared++;
                    flippedChosen += got is Joints c && Math.Abs(KinematicsCore.TurnDistance(c.J4, flipped.J4)) < 1e-6 && Math.Abs(c.J5 - flipped.J5) < 1e-6 ? 1 : 0;
                }
            }
        }
        Assert.True(compared > 4000, $"only {compared} comparisons");
        Assert.True(flippedChosen > 400, $"the flipped wrist was chosen only {flippedChosen} times");
    }

    [Theory]
    [MemberData(nameof(OpwModels))]
    public void Closest_OnAStreamedLine_IsTheChecksSolution(string name)
    {
        // The issue cursor's check of a 1 mm line from known joints: the public Closest (which the twins call) and the check's
        // arrival agree with the full search at every step of a walk, including where the walk passes near a singularity.
        RobotModel model = RobotModels.Get(name);
        IKinematics kin = model.Kinematics;
        Joints joints = Within(model, new Random(4551));
        Pose start = kin.Forward(joints);
        for (int i = 0; i < 400; i++)
        {
            Pose target = new(start.Position + new Vector(i % 2 == 0 ? 1 : -1, 0.25, -0.5) * (1 + i % 3), start.Rotation);
            Joints? got = kin.Closest(target, joints);
            Joints? want = KinematicsCore.ClosestOfAll((ISolver)kin, model, Affine.FromPose(target), joints, out _);
            Assert.True(want is null ? got is null : got is Joints g && SameBits.Of(want.Value, g), $"{name}, step {i}: {got} instead of {want}");
            if (got is not Joints next)
            {
                break;
            }
            joints = next;
            start = target;
        }
    }

    [Theory]
    [MemberData(nameof(OpwModels))]
    public void SolveRaw_IsTheOnePieceComputationBitForBit(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (OpwKinematics)model.Kinematics;
        bool kuka = model.Brand == "KUKA";
        var random = new Random(4552);
        Span<Joints> got = stackalloc Joints[KinematicsCore.MaxSolutions], want = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> gotConfig = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions], wantConfig = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        int solved = 0;
        for (int i = 0; i < 4000; i++)
        {
            Joints j = (i % 3) switch
            {
                0 => Random(random),
                1 => Random(random) with { J5 = i % 2 == 0 ? 0 : Near(random, 0) },
                _ => Random(random) with { J3 = Near(random, 90) },
            };
            Affine target = Affine.FromPose(kin.Forward(j));
            Joints reference = Random(random);
            int n = ((ISolver)kin).SolveRaw(target, reference, got, gotConfig);
            int m = FullSolveRaw(kin.Parameters, kuka, target, reference, want, wantConfig);
            Assert.Equal(m, n);
            for (int k = 0; k < n; k++)
            {
                Assert.True(SameBits.Of(want[k], got[k]), $"{name}, solution {k} of {j}: {got[k]} instead of {want[k]}");
                Assert.Equal(wantConfig[k], gotConfig[k]);
            }
            solved += n > 0 ? 1 : 0;
        }
        Assert.True(solved > 3000, $"only {solved} of the poses were solved");
    }

    internal static Joints Random(Random random) => new(Angle(random), Angle(random), Angle(random), Angle(random), Angle(random), Angle(random));

    internal static Joints Within(RobotModel model, Random random)
    {
        Span<double> v = stackalloc double[Joints.Count];
        for (int k = 0; k < Joints.Count; k++)
        {
            // Inside the limits, away from their ends, over at most one turn.
            double min = Math.Max(model.MinJoints[k], -180), max = Math.Min(model.MaxJoints[k], 180);
            v[k] = min + (max - min) * (0.1 + 0.8 * random.NextDouble());
        }
        return new Joints(v[0], v[1], v[2], v[3], v[4], v[5]);
    }

    private static Joints Nudged(Joints j, Random random, double degrees) => new(
        j.J1 + Step(random, degrees), j.J2 + Step(random, degrees), j.J3 + Step(random, degrees),
        j.J4 + Step(random, degrees), j.J5 + Step(random, degrees), j.J6 + Step(random, degrees));

    private static double Step(Random random, double degrees) => (random.NextDouble() * 2 - 1) * degrees;

    private static double Angle(Random random) => random.NextDouble() * 720 - 360;

    /// <summary>Within a hundredth of a degree of <paramref name="degrees"/>, down to a few ulps of it.</summary>
    internal static double Near(Random random, double degrees) => degrees + (random.NextDouble() * 2 - 1) * Math.Pow(10, -random.Next(2, 15));
    // SolveRaw as it was written in one piece (before the branches were split for Closest), to compare the split one with.
    private static int FullSolveRaw(OpwParameters _p, bool kuka, in Affine flange, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations)
    {
        Span<double> r = stackalloc double[6];
        ToCanonical(kuka, reference, r);
        double r4 = r[3], r6 = r[5];
        Affine w = new(flange.R02, flange.R01, -flange.R00, flange.R12, flange.R11, -flange.R10, flange.R22, flange.R21, -flange.R20, flange.Px, flange.Py, flange.Pz);
        double cx = w.Px - _p.C4 * w.R00, cy = w.Py - _p.C4 * w.R10, cz = w.Pz - _p.C4 * w.R20;
        double rho2 = cx * cx + cy * cy - _p.B * _p.B;
        if (rho2 < 0 || !double.IsFinite(rho2))
        {
            return 0;
        }
        double sFront = Math.Sqrt(rho2);
        // Wrist centre on axis 1 (shoulder singularity, b = 0): axis 1 is free and atan2 would only see rounding noise; keep the reference's.
        double baseAngle = cx * cx + cy * cy < 1e-18 ? r[0] : Math.Atan2(cy, cx);
        double e = -_p.A2, k = Math.Sqrt(_p.C3 * _p.C3 + e * e), psi = Math.Atan2(e, _p.C3), c2 = _p.C2;
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
                double t3 = elbow == 0 ? psi - asinD : psi - Math.PI + asinD;
                double g = t3 - psi;
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
                joints[count] = FromCanonical(kuka, t1, t2, t3, t4, t5, t6);
                configurations[count++] = new ArmConfiguration(back, down, false);
                joints[count] = FromCanonical(kuka, t1, t2, t3, t4 + Math.PI, -t5, t6 + Math.PI);
                configurations[count++] = new ArmConfiguration(back, down, true);
            }
        }
        return count;
    }

    internal static void ToCanonical(bool kuka, Joints j, Span<double> t)
    {
        if (kuka)
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

    private static Joints FromCanonical(bool kuka, double t1, double t2, double t3, double t4, double t5, double t6)
    {
        double a1 = KinematicsCore.WrapDegrees(t1), a2 = KinematicsCore.WrapDegrees(t2), a3 = KinematicsCore.WrapDegrees(t3);
        double a4 = KinematicsCore.WrapDegrees(t4), a5 = KinematicsCore.WrapDegrees(t5), a6 = KinematicsCore.WrapDegrees(t6);
        if (!kuka)
        {
            return new Joints(a1, a2, a3, a4, a5, a6);
        }
        return new Joints(Neg(a1), Wrap(a2 - 90), Wrap(a3 + 90), Neg(a4), a5, Neg(a6));

        static double Neg(double d) => d == -180 || d == 180 ? 180 : -d;
        static double Wrap(double d) => d > 180 ? d - 360 : d <= -180 ? d + 360 : d;
    }
}
