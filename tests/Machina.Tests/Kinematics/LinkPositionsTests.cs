namespace Machina.Tests.Kinematics;

/// <summary>RobotModel.LinkPositions: the arm's joints in space, to draw the arm (previews, user sketches).</summary>
public sealed class LinkPositionsTests
{
    private static void Near(Vector expected, Vector actual) =>
        Assert.True(expected.IsSimilar(actual, 1e-6), $"expected {expected}, got {actual}");

    [Fact]
    public void Irb120_AtZero_BaseShoulderElbowWristFlange_FromItsPublishedLengths()
    {
        // IRB 120: shoulder 290 mm up, upper arm 270 mm, forearm offset 70 mm, forearm 302 mm, flange 72 mm past the wrist.
        IReadOnlyList<Vector> points = RobotModels.Get("IRB 120").LinkPositions(new Joints(0, 0, 0, 0, 0, 0));

        Vector[] expected = [new(0, 0, 0), new(0, 0, 290), new(0, 0, 290), new(0, 0, 560), new(0, 0, 630), new(302, 0, 630), new(374, 0, 630)];
        Assert.Equal(expected.Length, points.Count);
        for (int i = 0; i < expected.Length; i++)
        {
            Near(expected[i], points[i]);
        }
    }

    [Fact]
    public void Irb120_AxisOneTurned_TheWholeArmTurnsAroundZ()
    {
        IReadOnlyList<Vector> points = RobotModels.Get("IRB 120").LinkPositions(new Joints(90, 0, 0, 0, 0, 0));

        Near(new Vector(0, 302, 630), points[5]);
        Near(new Vector(0, 374, 630), points[6]);
    }

    [Theory]
    [InlineData("IRB 120", 10, -20, 30, 40, 50, 60)]
    [InlineData("UR5e", 10, -100, 80, -70, -90, 20)]
    [InlineData("KR 6 R900 sixx", 15, -80, 95, 30, 40, -50)]
    public void LastPoint_IsTheFlangeOfForwardKinematics_AndTheLinksKeepTheirLengths(string model, double j1, double j2, double j3, double j4, double j5, double j6)
    {
        RobotModel arm = RobotModels.Get(model);
        var a = new Joints(j1, j2, j3, j4, j5, j6);
        var b = new Joints(-j1, j2 / 2, j3 / 3, -j4, j5 / 2, j6);

        IReadOnlyList<Vector> pa = arm.LinkPositions(a), pb = arm.LinkPositions(b);

        Near(arm.Kinematics.Forward(a).Position, pa[^1]);
        Near(arm.Kinematics.Forward(b).Position, pb[^1]);
        Assert.Equal(Vector.Zero, pa[0]);
        // A rigid link is as long whatever the joints: a wrong point would change some length.
        for (int i = 1; i < pa.Count; i++)
        {
            Assert.Equal((pa[i] - pa[i - 1]).Length, (pb[i] - pb[i - 1]).Length, 6);
        }
    }

    [Fact]
    public void Ur5e_AtZero_ShoulderAndElbowFromItsDhTable()
    {
        IReadOnlyList<Vector> points = RobotModels.Get("UR5e").LinkPositions(new Joints(0, 0, 0, 0, 0, 0));

        Near(new Vector(0, 0, 162.5), points[1]);
        Near(new Vector(-425, 0, 162.5), points[2]);
        Near(new Vector(-817.2, 0, 162.5), points[3]);
        Assert.Equal(7, points.Count);
    }

    [Fact]
    public void DhModel_Puma_LastPointIsTheFlange_LinksKeepTheirLengths()
    {
        var wide = new Joints(360, 360, 360, 360, 360, 360);
        RobotModel puma = RobotModel.FromDh("Puma 560", "Generic", DhConvention.Standard,
            [new(0, 90, 0), new(431.8, 0, 0), new(20.3, -90, 150.05), new(0, 90, 431.8), new(0, -90, 0), new(0, 0, 0)], new Joints(0, 0, 0, 0, 0, 0) - wide, wide);
        var a = new Joints(0, 0, 0, 0, 0, 0);
        var b = new Joints(30, 45, -60, 10, 20, 30);

        IReadOnlyList<Vector> pa = puma.LinkPositions(a), pb = puma.LinkPositions(b);

        Near(new Vector(452.1, -150.05, 431.8), pa[^1]);   // Corke's fkine(qz)
        Near(puma.Kinematics.Forward(b).Position, pb[^1]);
        for (int i = 1; i < pa.Count; i++)
        {
            Assert.Equal((pa[i] - pa[i - 1]).Length, (pb[i] - pb[i - 1]).Length, 6);
        }
    }

    [Fact]
    public void NonFiniteJoint_IsRefused()
    {
        Assert.Throws<ArgumentException>(() => RobotModels.Get("UR5e").LinkPositions(new Joints(double.NaN, 0, 0, 0, 0, 0)));
    }
}
