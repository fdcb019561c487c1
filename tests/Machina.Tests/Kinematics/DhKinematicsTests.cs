namespace Machina.Tests.Kinematics;

/// <summary>
/// <see cref="RobotModel.FromDh"/>: the Puma 560, the classic test arm, in both DH conventions against numbers printed in the textbooks,
/// the numerical inverse, and an ABB arm described by DH against the catalogue's own OPW model.
/// </summary>
public class DhKinematicsTests
{
    private static readonly Joints Wide = new(180, 180, 180, 180, 180, 180), MinusWide = new(-180, -180, -180, -180, -180, -180);

    // Puma 560, standard DH: P. Corke, "Robotics, Vision and Control" / Robotics Toolbox mdl_puma560: a2 = 0.4318, a3 = 0.0203,
    // d3 = 0.15005, d4 = 0.4318 m; α = 90°, 0, −90°, 90°, −90°, 0.
    private static RobotModel PumaStandard() => RobotModel.FromDh("Puma 560", "Generic", DhConvention.Standard,
        [new(0, 90, 0), new(431.8, 0, 0), new(20.3, -90, 150.05), new(0, 90, 431.8), new(0, -90, 0), new(0, 0, 0)], MinusWide, Wide,
        source: "Corke, Robotics Toolbox mdl_puma560");

    // Puma 560, modified DH: J. J. Craig, "Introduction to Robotics", example 3.3 (a2 = 431.8, a3 = 20.32, d3 = 149.09, d4 = 433.07 mm;
    // α₀..α₅ = 0, −90°, 0, −90°, 90°, −90°).
    private static RobotModel PumaModified() => RobotModel.FromDh("Puma 560 (Craig)", "Generic", DhConvention.Modified,
        [new(0, 0, 0), new(0, -90, 0), new(431.8, 0, 149.09), new(20.32, -90, 433.07), new(0, 90, 0), new(0, -90, 0)], MinusWide, Wide,
        source: "Craig, Introduction to Robotics, example 3.3");

    [Theory]
    // Corke: p560.fkine(qz) = [0.4521, −0.1500, 0.4318], rotation identity; p560.fkine(qr), qr = [0, 90°, −90°, 0, 0, 0]:
    // [0.0203, −0.1500, 0.8636], identity (0.1500 printed for d3 = 0.15005).
    [InlineData(0, 0, 0, 452.1, -150.05, 431.8)]
    [InlineData(90, 0, 0, 150.05, 452.1, 431.8)]    // axis 1 a quarter turn: the same point turned about Z
    public void Forward_PumaStandard_MatchesCorke(double j1, double j2, double j3, double x, double y, double z)
    {
        Pose p = PumaStandard().Kinematics.Forward(new Joints(j1, j2, j3, 0, 0, 0));
        var expected = new Pose(x, y, z, Rotation.FromAxisAngle(Vector.ZAxis, j1));
        Assert.True(expected.IsSimilar(p, 1e-9, 1e-9), p.ToString());
    }

    [Fact]
    public void Forward_PumaStandardReady_MatchesCorke()
    {
        Pose p = PumaStandard().Kinematics.Forward(new Joints(0, 90, -90, 0, 0, 0));
        Assert.True(new Pose(20.3, -150.05, 863.6, Rotation.Identity).IsSimilar(p, 1e-9, 1e-9), p.ToString());
    }

    [Theory]
    // Craig eq. 3.14 (wrist position of the Puma 560): px = c1·(a2c2 + a3c23 − d4s23) − d3s1, py = s1·(a2c2 + a3c23 − d4s23) + d3c1,
    // pz = −a3s23 − a2s2 − d4c23. Zero: (a2 + a3, d3, −d4); θ1 = 90°: (−d3, a2 + a3, −d4); θ2 = −90°: (d4, d3, a2 + a3).
    [InlineData(0, 0, 0, 431.8 + 20.32, 149.09, -433.07)]
    [InlineData(90, 0, 0, -149.09, 431.8 + 20.32, -433.07)]
    [InlineData(0, -90, 0, 433.07, 149.09, 431.8 + 20.32)]
    public void Forward_PumaModified_MatchesCraig(double j1, double j2, double j3, double x, double y, double z)
    {
        Pose p = PumaModified().Kinematics.Forward(new Joints(j1, j2, j3, 0, 0, 0));
        Assert.True(p.Position.IsSimilar(new Vector(x, y, z), 1e-9), p.ToString());
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Inverse_PumaRandomPoses_RoundTrip(bool standard)
    {
        RobotModel model = standard ? PumaStandard() : PumaModified();
        var random = new Random(560);
        for (int n = 0; n < 100; n++)
        {
            var joints = new Joints(R(random, 160), R(random, 120), R(random, 120), R(random, 170), 10 + R(random, 70) + 70, R(random, 170));
            Pose pose = model.Kinematics.Forward(joints);
            IReadOnlyList<Joints> all = model.Kinematics.Inverse(pose);
            Assert.True(all.Any(s => s.IsSimilar(joints, 1e-6)), $"#{n} {joints}: {all.Count} found: {string.Join(" ", all)}");
            Assert.All(all, s => Assert.True(model.Kinematics.Forward(s).IsSimilar(pose, 1e-6, 1e-6), $"{s} misses {pose}"));
            Assert.True(model.Kinematics.Closest(pose, joints)!.Value.IsSimilar(joints, 1e-6));
        }

        static double R(Random r, double range) => (r.NextDouble() * 2 - 1) * range;
    }

    [Fact]
    public void Inverse_PumaGenericPose_FindsEightConfigurations()
    {
        RobotModel puma = PumaStandard();
        Pose pose = puma.Kinematics.Forward(new Joints(20, 30, -40, 50, 60, 70));
        IReadOnlyList<Joints> all = puma.Kinematics.Inverse(pose);
        Assert.Equal(8, all.Count);
        Assert.Equal(8, all.Select(j => puma.Kinematics.ConfigurationOf(j)).Distinct().Count());
        foreach (ArmConfiguration c in all.Select(j => puma.Kinematics.ConfigurationOf(j)))
        {
            Assert.True(puma.Kinematics.Solve(pose, c)!.Value is Joints s && puma.Kinematics.Forward(s).IsSimilar(pose, 1e-6, 1e-6));
        }
    }

    [Fact]
    public void Inverse_OutOfReach_IsEmpty()
    {
        Assert.Empty(PumaStandard().Kinematics.Inverse(new Pose(2000, 0, 0, Rotation.Identity)));
        Assert.Null(PumaStandard().Kinematics.Closest(new Pose(2000, 0, 0, Rotation.Identity), default));
    }

    [Fact]
    public void Forward_Irb120AsDh_EqualsTheCatalogueModel()
    {
        // IRB 120 in standard DH (as in the ARTE toolbox's ABB tables): θ offsets 0, −90°, 0, 0, 0, 180°; the last DH frame is then tool0.
        RobotModel dh = RobotModel.FromDh("IRB 120 (DH)", "ABB", DhConvention.Standard,
            [new(0, -90, 290), new(270, 0, 0, -90), new(70, -90, 0), new(0, 90, 302), new(0, -90, 0), new(0, 0, 72, 180)],
            new Joints(-165, -110, -110, -160, -120, -400), new Joints(165, 110, 70, 160, 120, 400));
        RobotModel opw = RobotModels.Get("IRB 120");
        var random = new Random(120);
        for (int n = 0; n < 50; n++)
        {
            var joints = new Joints(R(random, 160), R(random, 100), R(random, 100), R(random, 150), R(random, 110), R(random, 300));
            Assert.True(opw.Kinematics.Forward(joints).IsSimilar(dh.Kinematics.Forward(joints), 1e-9, 1e-9), joints.ToString());
            Assert.Equal(opw.Kinematics.ConfigurationOf(joints).WristFlipped, dh.Kinematics.ConfigurationOf(joints).WristFlipped);
        }
        Assert.Equal(KinematicFamily.Dh, dh.Family);
        Assert.Equal("ABB", dh.Brand);

        static double R(Random r, double range) => (r.NextDouble() * 2 - 1) * range;
    }

    [Fact]
    public void Kinematics_Ur5AsDh_EqualsTheCatalogueModel()
    {
        // UR's own DH table (offset wrist, not spherical): the inverse then searches all six joints at once.
        RobotModel dh = RobotModel.FromDh("UR5 (DH)", "UR", DhConvention.Standard,
            [new(0, 90, 89.159), new(-425, 0, 0), new(-392.25, 0, 0), new(0, 90, 109.15), new(0, -90, 94.65), new(0, 0, 82.3)], MinusWide, Wide);
        RobotModel ur = RobotModels.Get("UR5");
        var random = new Random(5);
        for (int n = 0; n < 30; n++)
        {
            var joints = new Joints(R(random, 170), R(random, 170), R(random, 160), R(random, 170), 20 + R(random, 60) + 60, R(random, 170));
            Pose pose = ur.Kinematics.Forward(joints);
            Assert.True(pose.IsSimilar(dh.Kinematics.Forward(joints), 1e-9, 1e-9), joints.ToString());
            Assert.True(dh.Kinematics.Closest(pose, joints)!.Value.IsSimilar(joints, 1e-6));
            IReadOnlyList<Joints> all = dh.Kinematics.Inverse(pose);
            Assert.NotEmpty(all);
            Assert.All(all, s => Assert.True(dh.Kinematics.Forward(s).IsSimilar(pose, 1e-6, 1e-6)));
            Assert.All(all, s => Assert.Contains(ur.Kinematics.Inverse(pose), u => u.IsSimilar(s, 1e-5)));
        }

        static double R(Random r, double range) => (r.NextDouble() * 2 - 1) * range;
    }

    [Fact]
    public void Robot_WithDhModel_KeepsJointsAndPoseInStepLikeTheCatalogueModel()
    {
        // The same program on an ABB robot with the IRB 120 as a DH table and with the catalogue's IRB 120 (OPW): same joints, same pose,
        // same RAPID (confdata included).
        RobotModel dh = RobotModel.FromDh("IRB 120 (DH)", "ABB", DhConvention.Standard,
            [new(0, -90, 290), new(270, 0, 0, -90), new(70, -90, 0), new(0, 90, 302), new(0, -90, 0), new(0, 0, 72, 180)],
            new Joints(-165, -110, -110, -160, -120, -400), new Joints(165, 110, 70, 160, 120, 400), new Joints(250, 250, 250, 320, 320, 420));
        Robot withDh = Robot.Create("Bot", RobotType.ABB, dh), withOpw = Robot.Create("Bot", "ABB", "IRB 120");
        foreach (Robot bot in new[] { withDh, withOpw })
        {
            bot.AxesTo(new Joints(10, 20, -10, 30, 40, 50));
            bot.Move(0, 0, -50);
            bot.TransformTo(new Vector(300, 100, 400), Rotation.FlippedAroundY);
        }
        Joints a = withDh.GetCurrentAxes()!.Value, b = withOpw.GetCurrentAxes()!.Value;
        Assert.True(a.IsSimilar(b, 1e-6), $"{a} vs {b}");
        Assert.True(Vector.Distance(withDh.GetCurrentPosition()!.Value, withOpw.GetCurrentPosition()!.Value) < 1e-6);
        Assert.Equal(withOpw.GetWarnings().Count, withDh.GetWarnings().Count);
        var options = new CompileOptions { HumanComments = false };
        string[] rapidDh = withDh.Compile(RobotType.ABB, options).Files.SelectMany(f => f.Lines).ToArray();
        string[] rapidOpw = withOpw.Compile(RobotType.ABB, options).Files.SelectMany(f => f.Lines).ToArray();
        Assert.True(rapidOpw.SequenceEqual(rapidDh), string.Join("\n", rapidOpw.Zip(rapidDh).Where(p => p.First != p.Second).Select(p => $"{p.First} | {p.Second}")));
    }

    [Fact]
    public void FromDh_BadTable_ThrowsClearMessage()
    {
        DhJoint[] five = [new(0, 90, 0), new(1, 0, 0), new(1, 0, 0), new(0, 90, 1), new(0, -90, 0)];
        Assert.Contains("exactly six rows", Assert.Throws<ArgumentException>(() => RobotModel.FromDh("x", "Generic", DhConvention.Standard, five, MinusWide, Wide)).Message);
        DhJoint[] nan = [.. five, new(double.NaN, 0, 0)];
        Assert.Contains("Row 6", Assert.Throws<ArgumentException>(() => RobotModel.FromDh("x", "Generic", DhConvention.Standard, nan, MinusWide, Wide)).Message);
    }
}
