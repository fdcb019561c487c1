namespace Machina.Tests.Kinematics;

public class InverseKinematicsTests
{
    public static TheoryData<string> ModelNames()
    {
        var data = new TheoryData<string>();
        foreach (RobotModel m in RobotModels.All)
        {
            data.Add(m.Name);
        }
        return data;
    }

    [Fact]
    public void InverseAllTurns_Irb120_AddsTheOtherTurnsOfAxisSix()
    {
        RobotModel model = RobotModels.Get("IRB 120");
        Pose pose = model.Kinematics.Forward(new Joints(10, 20, -30, 40, 50, 30));
        var plain = model.Kinematics.Inverse(pose);
        var all = model.Kinematics.InverseAllTurns(pose);

        // Only axis 6 (±400°) has room for another turn: 30° is also -330° and 390°.
        Assert.Contains(new Joints(10, 20, -30, 40, 50, 30), all.Select(j => Round(j)));
        Assert.Contains(new Joints(10, 20, -30, 40, 50, -330), all.Select(j => Round(j)));
        Assert.Contains(new Joints(10, 20, -30, 40, 50, 390), all.Select(j => Round(j)));
        Assert.Equal(plain.Sum(j => j.J6 is >= -40 and <= 40 ? 3 : 2), all.Count);
        Assert.All(all, j => Assert.True(model.IsWithinLimits(j) && model.Kinematics.Forward(j).IsSimilar(pose, 1e-6, 1e-6)));
        Assert.Equal(all.Count, all.Distinct().Count());
    }

    [Fact]
    public void InverseAllTurns_Ur5_EveryAxisButTheElbowHasTwoTurns()
    {
        RobotModel model = RobotModels.Get("UR5");
        Pose pose = model.Kinematics.Forward(new Joints(10, -80, 70, -60, -90, 30));
        var plain = model.Kinematics.Inverse(pose);
        var all = model.Kinematics.InverseAllTurns(pose);

        Assert.Equal(8, plain.Count);
        Assert.Equal(8 * 32, all.Count); // ±360° on five axes: two values per joint; the elbow (±180°) has one
        Assert.Contains(new Joints(10 - 360, -80, 70, -60, -90, 30 - 360), all.Select(j => Round(j)));
        Assert.DoesNotContain(all, j => Math.Abs(j.J3) > 180);
        Assert.All(all, j => Assert.True(model.IsWithinLimits(j) && model.Kinematics.Forward(j).IsSimilar(pose, 1e-6, 1e-6)));
    }

    private static Joints Round(Joints j) =>
        new(Math.Round(j.J1, 6), Math.Round(j.J2, 6), Math.Round(j.J3, 6), Math.Round(j.J4, 6), Math.Round(j.J5, 6), Math.Round(j.J6, 6));

    [Theory]
    [MemberData(nameof(ModelNames))]
    public void Inverse_RandomReachablePoses_RoundTripWithinLimits(string name)
    {
        RobotModel model = RobotModels.Get(name);
        IKinematics kin = model.Kinematics;
        var random = new Random(1234);
        Span<Joints> buffer = stackalloc Joints[8];
        int checkedSolutions = 0;
        for (int trial = 0; trial < 200; trial++)
        {
            Joints source = RandomJoints(model, random);
            Pose pose = kin.Forward(source);
            int n = kin.Inverse(pose, buffer);
            if (n < 1)
            {
                Assert.Fail($"{name}: no solution for FK({source}) = {pose}");
            }
            bool foundSource = false;
            for (int i = 0; i < n; i++)
            {
                Joints j = buffer[i];
                Pose back = kin.Forward(j);
                if (!model.IsWithinLimits(j) || !back.IsSimilar(pose, 1e-6, 1e-6))
                {
                    Assert.Fail($"{name}: solution {j} (within limits: {model.IsWithinLimits(j)}) gives FK {back}, expected {pose}");
                }
                foundSource |= AngularlyEqual(j, source);
                checkedSolutions++;
            }
            Joints? closest = kin.Closest(pose, source);
            if (!foundSource || closest is null || !closest.Value.IsSimilar(source, 1e-6) || kin.ConfigurationOf(source) != kin.ConfigurationOf(closest.Value))
            {
                Assert.Fail($"{name}: original joints {source} found among the {n} solutions: {foundSource}; closest: {closest}");
            }
        }
        Assert.True(checkedSolutions >= 200);
    }

    [Theory]
    [MemberData(nameof(ModelNames))]
    public void Inverse_GenericPoseWithWideLimits_ReturnsEightDistinctSolutions(string name)
    {
        RobotModel model = RobotModels.Get(name);
        RobotModel wide = model.Family == KinematicFamily.Opw
            ? RobotModel.FromOpw("wide", model.Brand, model.Opw!.Value, Wide(-1), Wide(1))
            : RobotModel.FromUniversalRobotsDh("wide", model.UniversalRobotsDh!.Value, Wide(-1), Wide(1));
        // Poses well inside the workspace, away from singularities; at least one must give all eight solutions.
        Joints[] seeds = model.Family == KinematicFamily.Opw
            ? (model.Brand == "KUKA"
                ? [new(20, -100, 130, 30, 40, 50), new(20, -120, 150, 30, 40, 50), new(20, -90, 150, 30, 40, 50)]
                : [new(20, -20, 40, 30, 40, 50), new(20, -40, 60, 30, 40, 50), new(20, -20, 60, 30, 40, 50)])
            : [new(20, -70, 60, -80, 40, 50), new(20, -100, 120, -80, 40, 50), new(20, -120, 140, -60, 40, 50), new(20, -60, 130, -60, 40, 50)];
        Pose pose = default;
        IReadOnlyList<Joints> all = [];
        foreach (Joints seed in seeds)
        {
            pose = wide.Kinematics.Forward(seed);
            all = wide.Kinematics.Inverse(pose);
            if (all.Count == 8)
            {
                break;
            }
        }
        Assert.True(all.Count == 8, $"{all.Count} solutions: {string.Join(" ", all)}");
        var configs = all.Select(wide.Kinematics.ConfigurationOf).Distinct().ToList();
        Assert.Equal(8, configs.Count);
        foreach (ArmConfiguration c in configs)
        {
            Joints? j = wide.Kinematics.Solve(pose, c);
            Assert.NotNull(j);
            Assert.Equal(c, wide.Kinematics.ConfigurationOf(j.Value));
            Assert.True(wide.Kinematics.Forward(j.Value).IsSimilar(pose, 1e-6, 1e-6));
        }
    }

    [Theory]
    [InlineData("IRB 120")]
    [InlineData("KR 6 R900 sixx")]
    [InlineData("UR5e")]
    public void Inverse_FarAwayPose_ReturnsNoSolution(string name)
    {
        IKinematics kin = RobotModels.Get(name).Kinematics;
        var pose = new Pose(5000, 0, 500, Rotation.FlippedAroundY);
        Assert.Empty(kin.Inverse(pose));
        Assert.Null(kin.Closest(pose, default));
        Assert.Equal(0, kin.Inverse(pose, stackalloc Joints[8]));
    }

    [Fact]
    public void Inverse_WristSingularPose_ReturnsSolutionsThatRoundTrip()
    {
        IKinematics kin = RobotModels.Get("IRB 120").Kinematics;
        Pose pose = kin.Forward(new Joints(10, 20, -10, 0, 0, 30)); // J5 = 0: axes 4 and 6 aligned
        IReadOnlyList<Joints> all = kin.Inverse(pose);
        Assert.NotEmpty(all);
        foreach (Joints j in all)
        {
            Assert.True(kin.Forward(j).IsSimilar(pose, 1e-6, 1e-6), $"{j}");
        }
        // J4 + J6 carries the whole turn when the wrist is straight.
        Assert.Contains(all, j => Math.Abs(j.J5) < 1e-6 && Math.Abs(j.J4 + j.J6 - 30) < 1e-6);
    }

    [Theory]
    [MemberData(nameof(ModelNames))]
    public void Inverse_AtAndNearTheWristSingularity_EverySolutionRoundTrips(string name)
    {
        // Axis 5 exactly straight, or a hair away from it: axes 4 and 6 must still be solved consistently with each other.
        RobotModel model = RobotModels.Get(name);
        IKinematics kin = model.Kinematics;
        var random = new Random(99);
        double[] wrist = [0, 1e-12, -3e-10, 1e-8, 2e-6, -1e-4, 180];
        int solutions = 0;
        for (int trial = 0; trial < 60; trial++)
        {
            Joints r = RandomJoints(model, random);
            double j5 = wrist[trial % wrist.Length];
            if (j5 > model.MaxJoints.J5)
            {
                continue;
            }
            var source = new Joints(r.J1, r.J2, r.J3, r.J4, j5, r.J6);
            Pose pose = kin.Forward(source);
            IReadOnlyList<Joints> all = kin.Inverse(pose);
            Assert.NotEmpty(all);
            foreach (Joints j in all)
            {
                Pose back = kin.Forward(j);
                double mm = Vector.Distance(back.Position, pose.Position), deg = back.Rotation.AngleTo(pose.Rotation);
                Assert.True(mm < 1e-6 && deg < 1e-6, $"{name}: FK({source}) = {pose}; solution {j} is off by {mm:E2} mm and {deg:E2}°");
                solutions++;
            }
            Joints? closest = kin.Closest(pose, source);
            Assert.NotNull(closest);
            Assert.True(kin.Forward(closest.Value).IsSimilar(pose, 1e-6, 1e-6), $"{name}: closest {closest} to {source}");
        }
        Assert.True(solutions >= 50, $"{solutions} solutions checked");
    }

    [Theory]
    [InlineData("IRB 120", 0, 0, 0, 60, 0, -60)]
    [InlineData("IRB 2600-20/1.65", 30, 10, -20, -150, 0, 100)]
    [InlineData("KR 6 R700 sixx", 0, -90, 90, 60, 0, -60)]
    [InlineData("KR 16", 20, -80, 100, -120, 0, 30)]
    [InlineData("UR5", 0, -90, 90, 60, 0, -60)]
    [InlineData("UR10e", 30, -120, 100, -200, 180, 250)]
    public void Closest_AtAStraightWrist_KeepsTheCurrentJoints(string name, double j1, double j2, double j3, double j4, double j5, double j6)
    {
        // With axis 5 straight, axes 4 and 6 can share the turn in infinitely many ways; the current joints are one of them and the nearest.
        IKinematics kin = RobotModels.Get(name).Kinematics;
        var current = new Joints(j1, j2, j3, j4, j5, j6);
        Joints? closest = kin.Closest(kin.Forward(current), current);
        Assert.NotNull(closest);
        Assert.True(closest.Value.IsSimilar(current, 1e-6), $"{name}: closest to {current} is {closest}");
    }

    [Fact]
    public void Inverse_ShoulderSingularPose_ReturnsSolutionsThatRoundTrip()
    {
        // Wrist centre straight above axis 1: J2 tilts the arm back until the centre sits on the axis.
        IKinematics kin = RobotModels.Get("IRB 1200-7/0.7").Kinematics;
        // IRB 1200-7/0.7: a1 = 0; with J3 = -90 + atan(42/351) the forearm points up, so the wrist centre is on axis 1 at J2 = 0.
        double j3 = -90 + Math.Atan2(42, 351) * Angles.ToDegrees;
        Pose pose = kin.Forward(new Joints(0, 0, j3, 0, 30, 0));
        IReadOnlyList<Joints> all = kin.Inverse(pose);
        Assert.NotEmpty(all);
        foreach (Joints j in all)
        {
            Assert.True(kin.Forward(j).IsSimilar(pose, 1e-6, 1e-6), $"{j}");
        }
    }

    [Theory]
    [InlineData("ABB", 30, 10, 30, 20)]
    [InlineData("ABB", -60, 0, 45, 0)]
    [InlineData("KUKA", -30, -10, 30, -20)]
    public void Closest_WristCentreOnAxis1_KeepsTheCurrentAxis1(string brand, double j1, double j4, double j5, double j6)
    {
        // IRB 1200-7/0.7 geometry (a1 = 0, c2 = 350, c3 = 351, a2 = −42): lower arm 20° forward, elbow bent so that the wrist centre is
        // on axis 1. Axis 1 is then free; the nearest solution keeps the current value instead of one picked by rounding noise.
        RobotModel model = RobotModel.FromOpw("on axis 1", brand, RobotModels.Get("IRB 1200-7/0.7").Opw!.Value, Wide(-1), Wide(1));
        double psi = Math.Atan2(42, 351), k = Math.Sqrt(351.0 * 351 + 42 * 42), t2 = 20 * Angles.ToRadians;
        double t3 = (psi - Math.Acos(-350 * Math.Sin(t2) / k) - t2) * Angles.ToDegrees; // ABB axis 3
        var current = brand == "KUKA" ? new Joints(j1, 20 - 90, t3 + 90, j4, j5, j6) : new Joints(j1, 20, t3, j4, j5, j6);
        Pose pose = model.Kinematics.Forward(current);
        Joints? closest = model.Kinematics.Closest(pose, current);
        Assert.NotNull(closest);
        Assert.True(closest.Value.IsSimilar(current, 1e-6), $"closest to {current} is {closest}");
        Assert.All(model.Kinematics.Inverse(pose), j => Assert.True(model.Kinematics.Forward(j).IsSimilar(pose, 1e-6, 1e-6), $"{j}"));
    }

    [Theory]
    [InlineData("UR5", 0, -90, 90, 60, 0, -60, 6)] // straight wrist: its two wrist branches coincide (the other shoulder has 4)
    [InlineData("UR10e", 30, -100, 0, -80, 40, 10, 2)] // stretched elbow: elbow branches coincide; with the other wrist the arm is too short
    [InlineData("IRB 120", 0, 0, -76.95, 0, 30, 0, 1)] // stretched elbow (J3 = −90° + atan(70/302)); only one shoulder/wrist within limits
    public void Inverse_WhereBranchesCoincide_ReturnsEachSolutionOnce(string name, double j1, double j2, double j3, double j4, double j5, double j6, int expected)
    {
        RobotModel model = RobotModels.Get(name);
        double stretched = name == "IRB 120" ? -90 + Math.Atan2(70, 302) * Angles.ToDegrees : j3;
        Pose pose = model.Kinematics.Forward(new Joints(j1, j2, stretched, j4, j5, j6));
        IReadOnlyList<Joints> all = model.Kinematics.Inverse(pose);
        Assert.True(all.Count == expected, $"{all.Count} solutions: {string.Join(" ", all)}");
        for (int a = 0; a < all.Count; a++)
        {
            Assert.True(model.Kinematics.Forward(all[a]).IsSimilar(pose, 1e-6, 1e-6), $"{all[a]}");
            for (int b = a + 1; b < all.Count; b++)
            {
                Assert.False(all[a].IsSimilar(all[b], 1e-4), $"solution {all[a]} listed twice");
            }
        }
    }

    [Fact]
    public void Inverse_SolutionsBeyond180_UseTheTurnWithinLimits()
    {
        // KR 120 R2500 pro: A2 range is -140..-5, so the wrapped value must stay negative; UR J6 ±360.
        RobotModel kr = RobotModels.Get("KR 120 R2500 pro");
        Joints source = new(0, -100, 100, 0, 60, 0);
        Pose pose = kr.Kinematics.Forward(source);
        Assert.Contains(kr.Kinematics.Inverse(pose), j => j.IsSimilar(source, 1e-6));

        RobotModel ur = RobotModels.Get("UR5");
        Joints wound = new(10, -80, 70, -60, 50, 300);
        Joints? closest = ur.Kinematics.Closest(ur.Kinematics.Forward(wound), wound);
        Assert.NotNull(closest);
        Assert.Equal(300, closest.Value.J6, 6);
    }

    private static Joints Wide(double sign) => new(sign * 360, sign * 360, sign * 360, sign * 360, sign * 360, sign * 360);

    private static Joints RandomJoints(RobotModel model, Random random)
    {
        Span<double> v = stackalloc double[6];
        for (int i = 0; i < 6; i++)
        {
            double min = model.MinJoints[i], max = model.MaxJoints[i];
            // Stay within ±180° around the middle so the value is the unique representative picked by Closest, and away from J5 = 0.
            double lo = Math.Max(min, -179), hi = Math.Min(max, 179);
            v[i] = lo + (hi - lo) * random.NextDouble();
        }
        if (Math.Abs(v[4]) < 1)
        {
            v[4] = 5;
        }
        return Joints.FromArray(v);
    }

    private static bool AngularlyEqual(Joints a, Joints b)
    {
        for (int i = 0; i < 6; i++)
        {
            double d = Math.IEEERemainder(a[i] - b[i], 360);
            if (Math.Abs(d) > 1e-6)
            {
                return false;
            }
        }
        return true;
    }

    [Fact]
    public void WhyNoSolution_OutOfReach_Unreachable()
    {
        RobotModel model = RobotModels.Get("IRB 120");
        var pose = new Pose(new Vector(2000, 0, 300), Rotation.FlippedAroundY);

        Assert.Empty(model.Kinematics.Inverse(pose));
        KinematicIssue why = model.Kinematics.WhyNoSolution(pose)!;

        Assert.Equal(KinematicIssueKind.Unreachable, why.Kind);
        Assert.Equal("the target [2000, 0, 300] is out of reach of the ABB IRB 120.", why.Reason);
        Assert.Null(why.Joint);
        Assert.Null(why.Limit);
    }

    [Fact]
    public void WhyNoSolution_ReachableOnlyBeyondALimit_NamesTheJointAndTheNearestLimit()
    {
        // Axis 5 at 130° (limit ±120°): the other ways to reach this pose need axis 5 at −130° or break other limits further.
        RobotModel model = RobotModels.Get("IRB 120");
        Pose pose = model.Kinematics.Forward(new Joints(0, 0, 0, 0, 130, 0));

        Assert.Empty(model.Kinematics.Inverse(pose));
        Assert.Null(model.Kinematics.Closest(pose, new Joints(0, 0, 0, 0, 90, 0)));
        KinematicIssue why = model.Kinematics.WhyNoSolution(pose)!;

        Assert.Equal(KinematicIssueKind.JointLimit, why.Kind);
        Assert.Equal(5, why.Joint);
        Assert.Equal(120, Math.Abs(why.Limit!.Value));
        Assert.Contains("joint 5 at ", why.Reason, StringComparison.Ordinal);
        Assert.Contains("10° past its limit", why.Reason, StringComparison.Ordinal);
    }

    [Fact]
    public void WhyNoSolution_Reachable_Null()
    {
        RobotModel model = RobotModels.Get("UR5e");
        Pose pose = model.Kinematics.Forward(new Joints(10, -80, 70, -80, -90, 0));

        Assert.NotEmpty(model.Kinematics.Inverse(pose));
        Assert.Null(model.Kinematics.WhyNoSolution(pose));
    }
}
