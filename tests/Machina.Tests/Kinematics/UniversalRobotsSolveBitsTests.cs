namespace Machina.Tests.Kinematics;

/// <summary>
/// The UR solver takes each sine and cosine once (<see cref="Math.SinCos"/>, and the negated angle's from the angle's) and the
/// elbow's atan2 once per wrist: its solutions must be those of the full computation to the last bit, on every UR arm, for poses
/// all over the workspace, near the straight wrist and the stretched elbow, and for the forward kinematics too.
/// </summary>
public class UniversalRobotsSolveBitsTests
{
    public static TheoryData<string> UrModels() => UniversalRobotsClosedFormTests.UrModels();

    [Theory]
    [MemberData(nameof(UrModels))]
    public void SolveRaw_IsTheFullComputationBitForBit(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (UniversalRobotsKinematics)model.Kinematics;
        var random = new Random(4547);
        Span<Joints> got = stackalloc Joints[KinematicsCore.MaxSolutions], want = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> gotConfig = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions], wantConfig = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        int solved = 0;
        for (int i = 0; i < 20_000; i++)
        {
            Joints j = (i % 4) switch
            {
                0 => new Joints(Angle(random), Angle(random), Angle(random), Angle(random), Angle(random), Angle(random)),
                1 => new Joints(Angle(random), Angle(random), Angle(random), Angle(random), Near(random, 0), Angle(random)),          // wrist nearly straight
                2 => new Joints(Angle(random), Angle(random), Near(random, i % 8 == 2 ? 0 : 180), Angle(random), Angle(random), Angle(random)), // elbow nearly stretched or folded
                _ => new Joints(Angle(random), Angle(random), Angle(random), Angle(random), 0, Angle(random)),                        // wrist exactly straight
            };
            Affine target = Affine.FromPose(kin.Forward(j));
            var reference = new Joints(Angle(random), Angle(random), Angle(random), Angle(random), Angle(random), Angle(random));
            int n = ((ISolver)kin).SolveRaw(target, reference, got, gotConfig);
            int m = FullSolveRaw(kin.Parameters, target, reference, want, wantConfig);
            Assert.Equal(m, n);
            for (int k = 0; k < n; k++)
            {
                Assert.True(SameBits.Of(want[k], got[k]), $"{name}, solution {k} of {j}: {got[k]} instead of {want[k]}");
                Assert.Equal(wantConfig[k], gotConfig[k]);
            }
            solved += n > 0 ? 1 : 0;
        }
        Assert.True(solved > 19_000, $"only {solved} of the poses were solved: the comparison saw too few solutions");
    }

    [Theory]
    [MemberData(nameof(UrModels))]
    public void Forward_IsTheFullComputationBitForBit(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (UniversalRobotsKinematics)model.Kinematics;
        UniversalRobotsDh dh = kin.Parameters;
        var random = new Random(4548);
        for (int i = 0; i < 5000; i++)
        {
            var j = new Joints(Angle(random), Angle(random), Angle(random), Angle(random), Angle(random), Angle(random));
            const double r = Angles.ToRadians;
            Pose want = (FullDh(j.J1 * r, dh.D1, 0, 0, 1) * FullDh(j.J2 * r, 0, dh.A2, 1, 0) * FullDh(j.J3 * r, 0, dh.A3, 1, 0)
                * FullDh(j.J4 * r, dh.D4, 0, 0, 1) * FullDh(j.J5 * r, dh.D5, 0, 0, -1) * FullDh(j.J6 * r, dh.D6, 0, 1, 0)).ToPose();
            Assert.True(SameBits.Of(want, kin.Forward(j)), $"{name} at {j}");
        }
    }

    [Theory]
    [MemberData(nameof(UrModels))]
    public void Assess_IsConfigurationOfAndMeasure(string name)
    {
        var kin = (UniversalRobotsKinematics)RobotModels.Get(name).Kinematics;
        var random = new Random(4550);
        int backs = 0;
        for (int i = 0; i < 5000; i++)
        {
            var j = new Joints(Angle(random), Angle(random), Angle(random), Angle(random), i % 5 == 0 ? Near(random, 0) : Angle(random), Angle(random));
            (ArmConfiguration config, SingularityMeasure measure) = ((ISolver)kin).Assess(j);
            SingularityMeasure want = ((ISolver)kin).Measure(j);
            Assert.Equal(kin.ConfigurationOf(j), config);
            Assert.True(SameBits.Of(want.WristDegrees, measure.WristDegrees) && SameBits.Of(want.ElbowDegrees, measure.ElbowDegrees)
                && SameBits.Of(want.ShoulderMm, measure.ShoulderMm), $"{name} at {j}: {measure} instead of {want}");
            backs += config.ShoulderBack ? 1 : 0;
        }
        Assert.InRange(backs, 500, 4500);
    }

    private static Affine FullDh(double theta, double d, double a, double cosAlpha, double sinAlpha) =>
        Affine.Dh(Math.Cos(theta), Math.Sin(theta), d, a, cosAlpha, sinAlpha);

    /// <summary>The solver as it was before it shared its sines, cosines and the elbow's atan2 (session 26's code).</summary>
    internal static int FullSolveRaw(UniversalRobotsDh dh, in Affine t, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations)
    {
        double d1 = dh.D1, a2 = dh.A2, a3 = dh.A3, d4 = dh.D4, d5 = dh.D5, d6 = dh.D6;
        double px = t.Px - d6 * t.R02, py = t.Py - d6 * t.R12;
        double r = Math.Sqrt(px * px + py * py);
        if (!(r >= Math.Abs(d4) - 1e-9) || r == 0)
        {
            return 0;
        }
        double phi1 = Math.Atan2(py, px), phi2 = Math.Acos(Math.Clamp(d4 / r, -1, 1));
        int count = 0;
        for (int shoulder = 0; shoulder < 2; shoulder++)
        {
            double t1 = phi1 + (shoulder == 0 ? phi2 : -phi2) + Math.PI / 2;
            double c1 = Math.Cos(t1), s1 = Math.Sin(t1);
            Affine t1t = Affine.Dh(c1, s1, d1, 0, 0, 1).InverseRigid() * t;
            double ux = t.R00 * s1 - t.R10 * c1, uy = t.R01 * s1 - t.R11 * c1, c5 = t.R02 * s1 - t.R12 * c1;
            double s5Abs = Math.Sqrt(ux * ux + uy * uy);
            double t5Abs = Math.Atan2(s5Abs, c5);
            for (int wrist = 0; wrist < 2; wrist++)
            {
                double t5 = wrist == 0 ? t5Abs : -t5Abs;
                double sign = wrist == 0 ? 1 : -1;
                double t6 = s5Abs < 1e-12 ? reference.J6 * Angles.ToRadians : Math.Atan2(-uy * sign, ux * sign);
                Affine t14 = t1t * FullDh(t6, d6, 0, 1, 0).InverseRigid() * FullDh(t5, d5, 0, 0, -1).InverseRigid();
                double x = t14.Px, y = t14.Py;
                double c3 = (x * x + y * y - a2 * a2 - a3 * a3) / (2 * a2 * a3);
                if (c3 > 1 + 1e-12 || c3 < -1 - 1e-12)
                {
                    continue;
                }
                double t3Abs = Math.Acos(Math.Clamp(c3, -1, 1));
                double towardsWrist = Math.Atan2(y, x), arm234 = Math.Atan2(t14.R10, t14.R00);
                for (int elbow = 0; elbow < 2; elbow++)
                {
                    double t3 = elbow == 0 ? -t3Abs : t3Abs;
                    double t2 = towardsWrist - Math.Atan2(a3 * Math.Sin(t3), a2 + a3 * Math.Cos(t3));
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

    private static double Angle(Random random) => random.NextDouble() * 720 - 360;

    /// <summary>Within a hundredth of a degree of <paramref name="degrees"/>, down to a few ulps of it.</summary>
    private static double Near(Random random, double degrees) => degrees + (random.NextDouble() * 2 - 1) * Math.Pow(10, -random.Next(2, 15));
}
