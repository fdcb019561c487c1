namespace Machina.Tests.Kinematics;

/// <summary>
/// Forward kinematics against poses derived by hand from each arm's geometry (not from the solver's own chain):
/// the zero/home pose, a "tool down" pose and a pose with axis 1 turned. Lengths are typed again here from the data sheets.
/// </summary>
public class ForwardKinematicsTests
{
    private static readonly Rotation AbbHome = Rotation.FromAxisAngle(Vector.YAxis, 90);

    // name, a1, a2, c1, c2, c3, c4
    public static TheoryData<string, double, double, double, double, double, double> Opw() => new()
    {
        { "IRB 120", 0, -70, 290, 270, 302, 72 },
        { "IRB 140", 70, 0, 352, 360, 380, 65 },
        { "IRB 1200-5/0.9", 0, -42, 399.1, 448, 451, 82 },
        { "IRB 1200-7/0.7", 0, -42, 399.1, 350, 351, 82 },
        { "IRB 2600-12/1.65", 150, -115, 445, 700, 795, 85 },
        { "IRB 2600-20/1.65", 150, -115, 445, 700, 795, 85 },
        { "IRB 4600-60/2.05", 175, -175, 495, 900, 960, 135 },
        { "IRB 4600-40/2.55", 175, -175, 495, 1095, 1270, 135 },
        { "IRB 6700-200/2.60", 320, -200, 780, 1125, 1142.5, 200 },
        { "IRB 6700-205/2.80", 320, -200, 780, 1280, 1182.5, 200 },
        { "KR 6 R700 sixx", 25, -35, 400, 315, 365, 80 },
        { "KR 6 R900 sixx", 25, -35, 400, 455, 420, 80 },
        { "KR 10 R1100 sixx", 25, -35, 400, 560, 515, 80 },
        { "KR 16-2", 260, 35, 675, 680, 670, 158 },
        { "KR 120 R2500 pro", 350, 41, 675, 1150, 1000, 215 },
    };

    // name, d1, a2, a3, d4, d5, d6
    public static TheoryData<string, double, double, double, double, double, double> Ur() => new()
    {
        { "UR3", 151.9, -243.65, -213.25, 112.35, 85.35, 81.9 },
        { "UR5", 89.159, -425, -392.25, 109.15, 94.65, 82.3 },
        { "UR10", 127.3, -612, -572.3, 163.941, 115.7, 92.2 },
        { "UR3e", 151.85, -243.55, -213.2, 131.05, 85.35, 92.1 },
        { "UR5e", 162.5, -425, -392.2, 133.3, 99.7, 99.6 },
        { "UR10e", 180.7, -612.7, -571.55, 174.15, 119.85, 116.55 },
        { "UR16e", 180.7, -478.4, -360, 174.15, 119.85, 116.55 },
        { "UR20", 236.3, -862, -728.7, 201, 159.3, 154.3 },
        { "UR30", 236.3, -637, -503.7, 201, 159.3, 154.3 },
    };

    [Fact]
    public void Forward_Irb120Home_MatchesAbbPublishedTool0()
    {
        // RobotStudio / product specification: IRB 120 tool0 at all-zero joints is [374, 0, 630], quaternion [0.70711, 0, 0.70711, 0].
        Pose p = RobotModels.Get("IRB 120").Kinematics.Forward(default);
        AssertPose(new Pose(374, 0, 630, Rotation.FromQuaternion(Math.Sqrt(0.5), 0, Math.Sqrt(0.5), 0)), p);
    }

    [Fact]
    public void Forward_Ur5Zero_MatchesHandComputedPose()
    {
        // x = a2 + a3, y = −(d4 + d6), z = d1 − d5 (UR5 CB3 DH table).
        Pose p = RobotModels.Get("UR5").Kinematics.Forward(default);
        AssertPose(new Pose(-817.25, -191.45, -5.491, Rotation.FromAxisAngle(Vector.XAxis, 90)), p);
    }

    [Fact]
    public void Forward_Kr6R900Home_FlangeAlongX()
    {
        // KUKA home {A1 0, A2 -90, A3 90, A4 0, A5 0, A6 0}: x = a1 + c3 + c4 = 525, z = c1 + c2 − a2 = 890; FLANGE Z forward,
        // i.e. KRL A 0, B 90, C 0.
        Pose p = RobotModels.Get("KR 6 R900 sixx").Kinematics.Forward(new Joints(0, -90, 90, 0, 0, 0));
        AssertPose(new Pose(525, 0, 890, Rotation.FromYawPitchRoll(0, 90, 0)), p);
    }

    [Theory]
    [InlineData("IRB 120", 0, 0, 0, 0, 90, 0, 302, 0, 558, 0, 180, 0)]             // tool0 down: x = c3, z = c1 + c2 + 70 − c4
    [InlineData("IRB 140", 90, 0, 0, 0, 0, 0, 0, 515, 712, 90, 90, 0)]              // turned left: y = 70 + 380 + 65, z = 352 + 360
    [InlineData("KR 6 R900 sixx", 0, -90, 90, 0, 90, 0, 445, 0, 810, 180, 0, 180)]  // FLANGE down (KRL A 180, B 0, C 180)
    [InlineData("KR 16-2", 0, -90, 90, 0, 0, 0, 1088, 0, 1320, 0, 90, 0)]            // home: 260 + 670 + 158, 675 + 680 − 35 (forearm below axis 3)
    [InlineData("UR5e", 0, 0, 0, 0, 0, 0, -817.2, -232.9, 62.8, 0, 0, 90)]          // a2 + a3, −(d4 + d6), d1 − d5; Z along −Y
    [InlineData("UR10", 0, -90, 0, -90, 0, 0, 0, -256.141, 1427.3, 180, 0, -90)]    // upright: d1 − a2 − a3 + d5
    public void Forward_ExplicitReferencePoses_MatchHandValues(string name, double j1, double j2, double j3, double j4, double j5, double j6,
        double x, double y, double z, double yaw, double pitch, double roll)
    {
        Pose p = RobotModels.Get(name).Kinematics.Forward(new Joints(j1, j2, j3, j4, j5, j6));
        AssertPose(new Pose(x, y, z, Rotation.FromYawPitchRoll(yaw, pitch, roll)), p);
    }

    [Theory]
    [MemberData(nameof(Opw))]
    public void Forward_OpwReferencePoses_MatchGeometry(string name, double a1, double a2, double c1, double c2, double c3, double c4)
    {
        RobotModel model = RobotModels.Get(name);
        IKinematics kin = model.Kinematics;
        double reach = a1 + c3 + c4, height = c1 + c2 - a2;
        if (model.Brand == "ABB")
        {
            // Zero pose: lower arm up, forearm forward, tool0 Z forward (X down).
            AssertPose(new Pose(reach, 0, height, AbbHome), kin.Forward(new Joints(0, 0, 0, 0, 0, 0)));
            // Axis 5 at +90°: flange points down, wrist centre unchanged.
            AssertPose(new Pose(a1 + c3, 0, height - c4, Rotation.FlippedAroundY), kin.Forward(new Joints(0, 0, 0, 0, 90, 0)));
            // Axis 1 at +90° (turns to +Y), lower arm forward horizontal, forearm horizontal.
            AssertPose(new Pose(0, a1 + c2 + c3 + c4, c1 - a2, Rotation.FromAxisAngle(Vector.ZAxis, 90) * AbbHome), kin.Forward(new Joints(90, 90, -90, 0, 0, 0)));
            // Axis 4 is right-handed about the forearm (+X): J4 = +30 turns the flange +30° about world X.
            AssertPose(new Pose(reach, 0, height, Rotation.FromAxisAngle(Vector.XAxis, 30) * AbbHome), kin.Forward(new Joints(0, 0, 0, 30, 0, 0)));
        }
        else
        {
            // Home {0,-90,90,0,0,0}: FLANGE Z out of the flange (forward), X down: KRL A 0, B 90, C 0.
            AssertPose(new Pose(reach, 0, height, AbbHome), kin.Forward(new Joints(0, -90, 90, 0, 0, 0)));
            // A5 +90°: flange points down, KRL A 180, B 0, C 180.
            AssertPose(new Pose(a1 + c3, 0, height - c4, Rotation.FromYawPitchRoll(180, 0, 180)), kin.Forward(new Joints(0, -90, 90, 0, 90, 0)));
            // A1 +90° turns clockwise seen from above (towards −Y); A2 = 0 is the lower arm horizontal; A3 = 0 ⇒ forearm in line.
            AssertPose(new Pose(0, -(a1 + c2 + c3 + c4), c1 - a2, Rotation.FromAxisAngle(Vector.ZAxis, -90) * AbbHome), kin.Forward(new Joints(90, 0, 0, 0, 0, 0)));
            // A4 is left-handed about the forearm: A4 = +30 turns the flange −30° about world X.
            AssertPose(new Pose(reach, 0, height, Rotation.FromAxisAngle(Vector.XAxis, -30) * AbbHome), kin.Forward(new Joints(0, -90, 90, 30, 0, 0)));
            // A4 and A6 are left-handed about the tool axis: A6 = +30 turns the flange −30° about its own Z.
            AssertPose(new Pose(reach, 0, height, AbbHome * Rotation.FromAxisAngle(Vector.ZAxis, -30)), kin.Forward(new Joints(0, -90, 90, 0, 0, 30)));
        }
    }

    [Theory]
    [MemberData(nameof(Ur))]
    public void Forward_UrReferencePoses_MatchGeometry(string name, double d1, double a2, double a3, double d4, double d5, double d6)
    {
        IKinematics kin = RobotModels.Get(name).Kinematics;
        // All zero: arm stretched along −X, flange Z along −Y.
        AssertPose(new Pose(a2 + a3, -(d4 + d6), d1 - d5, Rotation.FromAxisAngle(Vector.XAxis, 90)), kin.Forward(default));
        // Upright [0,-90,0,-90,0,0]: flange Z along −Y, X along −X.
        Rotation upright = Rotation.FromAxes(new Vector(-1, 0, 0), new Vector(0, 0, -1));
        AssertPose(new Pose(0, -(d4 + d6), d1 - a2 - a3 + d5, upright), kin.Forward(new Joints(0, -90, 0, -90, 0, 0)));
        // Same with the base turned +90°.
        AssertPose(new Pose(d4 + d6, 0, d1 - a2 - a3 + d5, Rotation.FromAxisAngle(Vector.ZAxis, 90) * upright), kin.Forward(new Joints(90, -90, 0, -90, 0, 0)));
    }

    private static void AssertPose(Pose expected, Pose actual) =>
        Assert.True(expected.IsSimilar(actual, 1e-6, 1e-6), $"expected {expected}, got {actual}");
}
