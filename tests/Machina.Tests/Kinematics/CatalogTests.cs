using System.Globalization;

namespace Machina.Tests.Kinematics;

/// <summary>
/// Every catalogued model against numbers written in its source, not computed by Machina: the flange (ABB tool0, KUKA FLANGE,
/// UR tool0) at the all-zero joints and at one more joint set. The expected values are the source's own chain (URDF joint origins,
/// axes and the tool0 frame of the named file, or UR's DH table chained as in UR's ur_macro.xacro) evaluated outside Machina and
/// written literally in catalog-poses.txt (one pose a line, each model's source above it), in mm and as a quaternion (w, x, y, z).
/// At the zero pose each is the plain sum of the file's joint origins. The three ABB models without a ROS-Industrial description
/// are checked against their product-specification lengths (sums written out below). Joint values are the brand's own (KUKA
/// A2 = 0: lower arm horizontal).
/// </summary>
public class CatalogTests
{
    private static Joints J(double a, double b, double c, double d, double e, double f) => new(a, b, c, d, e, f);

    private sealed record SourcePose(string Model, Joints Joints, double X, double Y, double Z, double Qw, double Qx, double Qy, double Qz);

    /// <summary>The poses of catalog-poses.txt (one a line: model | joints | x y z | qw qx qy qz), then those written out below.</summary>
    private static readonly SourcePose[] Poses =
    [
        .. ReadPoses("catalog-poses.txt"),
        // No ROS-Industrial description: ABB product specification lengths (see docs/kinematics.md). Zero: [a1 + c3 + c4, 0, c1 + c2 − a2],
        // tool0 Z forward; axis 5 at 90°: [a1 + c3, 0, c1 + c2 − a2 − c4], tool0 Z down.
        new("IRB 140", J(0, 0, 0, 0, 0, 0), 70 + 380 + 65, 0, 352 + 360 - 0, 0.70711, 0, 0.70711, 0),
        new("IRB 140", J(0, 0, 0, 0, 90, 0), 70 + 380, 0, 352 + 360 - 0 - 65, 0, 0, 1, 0),
        new("IRB 2600-20/1.65", J(0, 0, 0, 0, 0, 0), 150 + 795 + 85, 0, 445 + 700 + 115, 0.70711, 0, 0.70711, 0),
        new("IRB 2600-20/1.65", J(0, 0, 0, 0, 90, 0), 150 + 795, 0, 445 + 700 + 115 - 85, 0, 0, 1, 0),
        new("IRB 6700-205/2.80", J(0, 0, 0, 0, 0, 0), 320 + 1182.5 + 200, 0, 780 + 1280 + 200, 0.70711, 0, 0.70711, 0),
        new("IRB 6700-205/2.80", J(0, 0, 0, 0, 90, 0), 320 + 1182.5, 0, 780 + 1280 + 200 - 200, 0, 0, 1, 0),
    ];

    private static IEnumerable<SourcePose> ReadPoses(string file)
    {
        using Stream stream = typeof(CatalogTests).Assembly.GetManifestResourceStream("Machina.Tests." + file)!;
        using var reader = new StreamReader(stream);
        foreach (string line in reader.ReadToEnd().Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0 && !l.StartsWith('#')))
        {
            string[] cells = line.Split('|', StringSplitOptions.TrimEntries);
            double[] j = Numbers(cells[1]), p = Numbers(cells[2]), q = Numbers(cells[3]);
            yield return new SourcePose(cells[0], J(j[0], j[1], j[2], j[3], j[4], j[5]), p[0], p[1], p[2], q[0], q[1], q[2], q[3]);
        }
    }

    private static double[] Numbers(string cell) =>
        [.. cell.Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(w => double.Parse(w, CultureInfo.InvariantCulture))];

    public static TheoryData<string> Models()
    {
        var data = new TheoryData<string>();
        foreach (RobotModel m in RobotModels.All)
        {
            data.Add(m.Name);
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void Forward_CatalogModel_MatchesItsSource(string name)
    {
        RobotModel model = RobotModels.Get(name);
        SourcePose[] rows = Poses.Where(p => p.Model == name).ToArray();
        Assert.True(rows.Length >= 2, $"{name}: every catalogued model needs its zero pose and one more pose from its source in this table.");
        foreach (SourcePose row in rows)
        {
            var expected = new Pose(row.X, row.Y, row.Z, Rotation.FromQuaternion(row.Qw, row.Qx, row.Qy, row.Qz));
            Pose actual = model.Kinematics.Forward(row.Joints);
            // 0.1 mm: the sources give lengths to 0.1 mm or better; some KUKA files round their frame rotations (1.5708 for π/2).
            Assert.True(expected.IsSimilar(actual, 0.1, 0.01), $"{name} at {row.Joints}: source says {expected}, Machina gives {actual}");
        }
    }

    [Fact]
    public void All_HasAtLeast60ArmsEachWithSourceLimitsAndSpeeds()
    {
        Assert.True(RobotModels.All.Count >= 60, $"only {RobotModels.All.Count} models");
        Assert.Equal(RobotModels.All.Count, RobotModels.All.Select(m => m.Name).Distinct().Count());
        foreach (RobotModel m in RobotModels.All)
        {
            Assert.False(string.IsNullOrWhiteSpace(m.Source), m.Name);
            Assert.Same(m, RobotModels.Find(m.Name));
            // The IRB 6700-205/2.80 is the one arm whose joint speeds no source gave (kept because users' code names it).
            Assert.True(m.MaxJointSpeeds is not null || m.Name == "IRB 6700-205/2.80", $"{m.Name} has no joint speeds");
        }
        Assert.True(RobotModels.All.Count(m => m.Brand == "ABB") >= 20);
        Assert.True(RobotModels.All.Count(m => m.Brand == "KUKA") >= 30);
        Assert.Equal(9, RobotModels.All.Count(m => m.Brand == "UR"));
    }

    [Theory]
    [InlineData("IRB 4600-20/2.50")]
    [InlineData("KR 5 arc")]
    [InlineData("KR 16-2")]
    [InlineData("KR 16")]     // the name used before: still found
    public void Find_NewAndOldNames_AreCatalogued(string name) => Assert.NotNull(RobotModels.Find(name));

    // Joint ranges that looked mirrored or copied (issue 13), in the brand's own signs. Sources in docs/kinematics.md.
    [Theory]
    // ABB IRB 2600 product specification: axis 2 +155° (forward) to −95°; axis 3 +75° to −180°. (ROS-Industrial's irb2600_12_165_macro
    // has axis 2 −155/+95 and axis 3 −155/+75: mirrored there, not here; its axis +Y is ABB's positive direction.)
    [InlineData("IRB 2600-12/1.65", 2, -95, 155)]
    [InlineData("IRB 2600-12/1.65", 3, -180, 75)]
    // KR QUANTEC: A2 −140° to −5° (kuka_robot_descriptions, every QUANTEC); the kuka_experimental kr120r2500pro URDF repeats the
    // KR 16-2 ranges (−155/35, −130/154) and speeds verbatim, a copy.
    [InlineData("KR 120 R2500 pro", 2, -140, -5)]
    [InlineData("KR 120 R2500 pro", 3, -120, 155)]
    // ABB IRB 140: axis 2 +110/−90, axis 3 +50/−230, axis 5 ±115 (sources disagree on axis 5, ±115 or ±120: the narrower is kept).
    [InlineData("IRB 140", 2, -90, 110)]
    [InlineData("IRB 140", 3, -230, 50)]
    [InlineData("IRB 140", 5, -115, 115)]
    // UR elbow: ±180° — the arm's own construction stops it there (Universal_Robots_ROS2_Description config/*/joint_limits.yaml).
    [InlineData("UR5e", 3, -180, 180)]
    [InlineData("UR20", 3, -180, 180)]
    [InlineData("UR3", 3, -180, 180)]
    // IRB 1200: axis 2 +130° on the 5/0.9, +135° on the 7/0.7 (abb_experimental irb1200 macros).
    [InlineData("IRB 1200-5/0.9", 2, -100, 130)]
    [InlineData("IRB 1200-7/0.7", 2, -100, 135)]
    public void Limits_CheckedAxes_MatchTheSources(string name, int axis, double min, double max)
    {
        RobotModel m = RobotModels.Get(name);
        Assert.Equal(min, m.MinJoints[axis - 1]);
        Assert.Equal(max, m.MaxJoints[axis - 1]);
    }

    [Fact]
    public void Kr16_ForearmOffsetAndBaseHeight_MatchRosIndustrial()
    {
        // kuka_experimental kuka_kr16_support/urdf/kr16_2_macro.xacro: joint_a4 origin z = −0.035 (the forearm runs 35 mm below axis 3),
        // joint_a6-flange x = 0.158. Home {0, −90, 90, 0, 0, 0}: x = 0.260 + 0.670 + 0.158, z = 0.675 + 0.680 − 0.035.
        Pose home = RobotModels.Get("KR 16-2").Kinematics.Forward(J(0, -90, 90, 0, 0, 0));
        Assert.True(home.Position.IsSimilar(new Vector(1088, 0, 1320), 1e-6), home.ToString());
        // abb_experimental irb1200 macros: joint_1 origin z = 0.3991 (the IRB 1200 axis 2 is 399.1 mm above the base).
        Assert.Equal(399.1, RobotModels.Get("IRB 1200-5/0.9").Opw!.Value.C1);
        Assert.Equal(399.1, RobotModels.Get("IRB 1200-7/0.7").Opw!.Value.C1);
    }
}
