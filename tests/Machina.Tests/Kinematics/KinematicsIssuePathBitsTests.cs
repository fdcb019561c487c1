namespace Machina.Tests.Kinematics;

/// <summary>
/// What the issuing thread's check computes per streamed move, made cheaper without changing a bit: the ortho-parallel forward
/// kinematics, configuration and singularity measure (one sine of each angle, <c>Assess</c> sharing them) against the computation as
/// it was written before; a joint's fit to its limits (the nearest turn first) against the search of every turn; axis 1's offset
/// angle for b = 0 against atan2; and the joint speed warning of a line at ratios just above and below the maximum.
/// </summary>
public class KinematicsIssuePathBitsTests
{
    [Theory]
    [MemberData(nameof(OpwClosestTests.OpwModels), MemberType = typeof(OpwClosestTests))]
    public void Forward_ConfigurationAndMeasure_AreTheOldComputationBitForBit(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (OpwKinematics)model.Kinematics;
        var solver = (ISolver)kin;
        bool kuka = model.Brand == "KUKA";
        OpwParameters p = kin.Parameters;
        double e = -p.A2, psi = Math.Atan2(e, p.C3);
        var random = new Random(5201);
        int back = 0, down = 0, flipped = 0, nearWrist = 0, nearElbow = 0;
        Span<double> t = stackalloc double[6];
        for (int i = 0; i < 6000; i++)
        {
            Joints j = (i % 6) switch
            {
                0 => OpwClosestTests.Random(random),
                1 => OpwClosestTests.Random(random) with { J5 = OpwClosestTests.Near(random, random.Next(3) * 180 - 180) },   // wrist nearly straight
                2 => OpwClosestTests.Random(random) with { J5 = 0 },
                3 => OpwClosestTests.Random(random) with { J3 = ElbowStretchedAt(kuka, psi, random) },                       // elbow nearly stretched
                4 => OpwClosestTests.Within(model, random),
                _ => OpwClosestTests.Random(random) with { J2 = OpwClosestTests.Near(random, 0), J3 = OpwClosestTests.Near(random, 0) },
            };
            OpwClosestTests.ToCanonical(kuka, j, t);
            double reach = p.A1 + p.C2 * Math.Sin(t[1]) + p.C3 * Math.Cos(t[1] + t[2]) + e * Math.Sin(t[1] + t[2]);
            var config = new ArmConfiguration(reach < 0, Math.Cos(t[2] - psi) < 0, Math.Sin(t[4]) < 0);
            var measure = new SingularityMeasure(
                Math.Asin(Math.Min(1, Math.Abs(Math.Sin(t[4])))) * Angles.ToDegrees, Math.Asin(Math.Min(1, Math.Abs(Math.Cos(t[2] - psi)))) * Angles.ToDegrees, Math.Abs(reach));

            Assert.True(SameBits.Of(OldForward(p, t), kin.Forward(j)), $"{name}: forward kinematics of {j}");
            Assert.Equal(config, kin.ConfigurationOf(j));
            Assert.True(Same(measure, solver.Measure(j)), $"{name}: measure of {j}");
            (ArmConfiguration c, SingularityMeasure m) = solver.Assess(j);
            Assert.Equal(config, c);
            Assert.True(Same(measure, m), $"{name}: assessed measure of {j}");
            back += config.ShoulderBack ? 1 : 0;
            down += config.ElbowDown ? 1 : 0;
            flipped += config.WristFlipped ? 1 : 0;
            nearWrist += measure.WristDegrees < KinematicChecks.WristSingularityDegrees ? 1 : 0;
            nearElbow += measure.ElbowDegrees < KinematicChecks.ElbowSingularityDegrees ? 1 : 0;
        }
        // Every configuration flag both ways, and both singularities met.
        Assert.InRange(back, 100, 5900);
        Assert.InRange(down, 100, 5900);
        Assert.InRange(flipped, 100, 5900);
        Assert.True(nearWrist > 1000 && nearElbow > 500, $"{nearWrist} near the straight wrist, {nearElbow} near the stretched elbow");
    }

    [Fact]
    public void FitJoint_IsTheSearchOfEveryTurn_BitForBit()
    {
        var random = new Random(5202);
        (double Min, double Max)[] ranges = [(-165, 165), (-110, 110), (-400, 400), (-5, 5), (0, 0.5), (-1000, 1000), (-180, 180), (-360, 360)];
        int shortWay = 0;
        for (int i = 0; i < 400_000; i++)
        {
            (double min, double max) = ranges[i % ranges.Length];
            double value = random.NextDouble() * 360 - 180;
            double reference = (i % 7) switch
            {
                0 => value + random.NextDouble() * 2 - 1,                                                  // a streamed move
                1 => value + 360 * random.Next(-3, 4) + (random.Next(2) == 0 ? 179 : -179) + (random.NextDouble() - 0.5) * 1e-9,   // the short way's edge
                2 => value + 360 * random.Next(-3, 4) + (random.Next(2) == 0 ? 180 : -180) * (1 + (random.NextDouble() - 0.5) * 1e-15),   // half a turn: a tie
                3 => random.NextDouble() * 4000 - 2000,
                4 => (random.Next(2) == 0 ? min : max) + (random.NextDouble() - 0.5) * 4e-9,             // on a limit
                5 => random.NextDouble() * 2e6 - 1e6,                                                      // far, around the short way's bound
                _ => random.NextDouble() * 720 - 360,
            };
            if (i % 11 == 0)
            {
                value = (random.Next(2) == 0 ? min : max) + (random.NextDouble() - 0.5) * 4e-9;           // the value on a limit
            }
            bool want = KinematicsCore.FitJointAnyTurn(value, reference, min, max, out double wanted);
            bool got = KinematicsCore.FitJoint(value, reference, min, max, out double fitted);
            Assert.Equal(want, got);
            Assert.True(BitConverter.DoubleToInt64Bits(wanted) == BitConverter.DoubleToInt64Bits(fitted), $"{value:R} near {reference:R} in [{min}, {max}]: {fitted:R} instead of {wanted:R}");
            double nearest = value + 360.0 * Math.Round((reference - value) / 360.0);
            shortWay += nearest >= min - 1e-9 && nearest <= max + 1e-9 && Math.Abs(nearest - reference) < KinematicsCore.NearTurnDegrees ? 1 : 0;
        }
        // Both ways were taken, often.
        Assert.InRange(shortWay, 100_000, 300_000);
    }

    [Fact]
    public void ShoulderOffsetAngle_ForBZero_IsAtan2BitForBit()
    {
        // TryShoulder takes atan2(+0, ±ρ) as +0 in front (ρ ≥ +0) and π behind (−ρ, −0 included) without calling it.
        foreach (double s in new[] { 0.0, double.Epsilon, 1e-300, 0.5, 1, 1234.5, 1e300 })
        {
            Assert.Equal(BitConverter.DoubleToInt64Bits(0.0), BitConverter.DoubleToInt64Bits(Math.Atan2(0.0, s)));
            Assert.Equal(BitConverter.DoubleToInt64Bits(Math.PI), BitConverter.DoubleToInt64Bits(Math.Atan2(0.0, -s)));
        }
        Assert.All(RobotModels.All.Where(m => m.Kinematics is OpwKinematics), m => Assert.Equal(0.0, ((OpwKinematics)m.Kinematics).Parameters.B));
    }

    [Theory]
    [InlineData(0.999)]
    [InlineData(1.001)]
    public void Line_JointSpeedNearTheMaximum_WarnsExactlyAbove(double ratio)
    {
        RobotModel irb120 = RobotModels.Get("IRB 120");
        var random = new Random(5203);
        int warned = 0;
        for (int i = 0; i < 300; i++)
        {
            Joints start = OpwClosestTests.Within(irb120, random) with { J5 = 30 + random.NextDouble() * 60 };
            Pose from = irb120.Kinematics.Forward(start);
            var direction = new Vector(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            var target = new Pose(from.Position + direction * (1.5 / direction.Length), from.Rotation);   // one sample
            if (KinematicChecks.Check(irb120, start, target, KinematicMotion.Linear, 0, Pose.Identity, out Joints? arrival).Count > 0 || arrival is not Joints end)
            {
                continue;   // near a singularity or a limit: the speed's warning would not be alone
            }
            // The joint speeds the line's one step asks for at 1 mm/s, and the speed that puts the worst at `ratio` of its maximum.
            Joints max = irb120.MaxJointSpeeds!.Value;
            double length = Vector.Distance(from.Position, target.Position);
            int worst = 0;
            double worstPerMm = 0;
            for (int k = 0; k < Joints.Count; k++)
            {
                double perMm = Math.Abs(end[k] - start[k]) / length / max[k];
                if (perMm > worstPerMm)
                {
                    worstPerMm = perMm;
                    worst = k;
                }
            }
            double speed = ratio / worstPerMm;
            IReadOnlyList<KinematicIssue> issues = KinematicChecks.Check(irb120, start, target, KinematicMotion.Linear, speed, Pose.Identity, out Joints? again);
            Assert.Equal(arrival, again);
            if (ratio < 1)
            {
                Assert.Empty(issues);
                continue;
            }
            KinematicIssue issue = Assert.Single(issues);
            Assert.Equal(KinematicIssueKind.JointSpeed, issue.Kind);
            Assert.Contains($"joint {worst + 1} would need {Num.F(ratio * max[worst], 0)}°/s, above its maximum of {Num.F(max[worst], 0)}°/s", issue.Reason);
            warned++;
        }
        Assert.True(ratio < 1 || warned > 250, $"{warned} warnings");
    }

    private static bool Same(SingularityMeasure a, SingularityMeasure b) =>
        SameBits.Of(a.WristDegrees, b.WristDegrees) && SameBits.Of(a.ElbowDegrees, b.ElbowDegrees) && SameBits.Of(a.ShoulderMm, b.ShoulderMm);

    /// <summary>Axis 3 (brand degrees) within a hundredth of a degree of the stretched elbow (cos(θ3 − ψ) = 0).</summary>
    private static double ElbowStretchedAt(bool kuka, double psi, Random random)
    {
        double canonical = (psi + Math.PI / 2) * Angles.ToDegrees;
        return OpwClosestTests.Near(random, kuka ? canonical + 90 : canonical);
    }

    // The forward kinematics as it was written before: each sine and cosine by its own call, the five rotations multiplied out.
    private static Pose OldForward(OpwParameters p, ReadOnlySpan<double> t)
    {
        double e = -p.A2, phi = t[1] + t[2];
        double s = p.A1 + p.C2 * Math.Sin(t[1]) + p.C3 * Math.Cos(phi) + e * Math.Sin(phi);
        double z = p.C1 + p.C2 * Math.Cos(t[1]) - p.C3 * Math.Sin(phi) + e * Math.Cos(phi);
        double c1 = Math.Cos(t[0]), s1 = Math.Sin(t[0]);
        Affine r = Affine.RotZ(c1, s1) * Affine.RotY(Math.Cos(phi), Math.Sin(phi)) * Affine.RotX(Math.Cos(t[3]), Math.Sin(t[3]))
            * Affine.RotY(Math.Cos(t[4]), Math.Sin(t[4])) * Affine.RotX(Math.Cos(t[5]), Math.Sin(t[5]));
        double wx = s * c1 - p.B * s1, wy = s * s1 + p.B * c1;
        Affine w = r.WithTranslation(wx + p.C4 * r.R00, wy + p.C4 * r.R10, z + p.C4 * r.R20);
        return new Affine(-w.R02, w.R01, w.R00, -w.R12, w.R11, w.R10, -w.R22, w.R21, w.R20, w.Px, w.Py, w.Pz).ToPose();
    }
}
