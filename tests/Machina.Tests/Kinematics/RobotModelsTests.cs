namespace Machina.Tests.Kinematics;

public class RobotModelsTests
{
    [Fact]
    public void Models_CannotBeChangedThroughACast()
    {
        var models = (IList<RobotModel>)Robot.Models;
        Assert.Throws<NotSupportedException>(() => models[0] = models[1]);
        Assert.Equal("IRB 120", Robot.Models.First(m => m.Brand == "ABB").Name);
    }

    [Fact]
    public void All_ContainsEveryRequiredModel()
    {
        string[] required = ["UR3", "UR5", "UR10", "UR3e", "UR5e", "UR10e", "UR16e", "UR20", "UR30", "IRB 120", "IRB 140", "IRB 1200-5/0.9", "IRB 1200-7/0.7",
            "IRB 2600-12/1.65", "IRB 4600-60/2.05", "IRB 4600-40/2.55", "IRB 6700-200/2.60", "KR 6 R700 sixx", "KR 6 R900 sixx", "KR 10 R1100 sixx", "KR 16", "KR 120 R2500 pro"];
        foreach (string name in required)
        {
            Assert.NotNull(RobotModels.Find(name));
        }
        Assert.All(RobotModels.All, m => Assert.False(string.IsNullOrWhiteSpace(m.Source)));
    }

    [Fact]
    public void Find_IgnoresCaseAndSpaces()
    {
        Assert.Equal("IRB 1200-7/0.7", RobotModels.Find("irb1200-7/0.7")?.Name);
        Assert.Equal("UR5e", RobotModels.Find("ur5E")?.Name);
        Assert.Null(RobotModels.Find("UR7"));
    }

    [Fact]
    public void Get_UnknownName_ListsCloseNames()
    {
        var ex = Assert.Throws<ArgumentException>(() => RobotModels.Get("IRB 4600"));
        Assert.Contains("IRB 4600-60/2.05", ex.Message);
        Assert.Contains("IRB 4600-40/2.55", ex.Message);
    }

    [Fact]
    public void FromOpw_BadInput_ThrowsClearMessage()
    {
        var p = new OpwParameters(0, -70, 0, 290, 270, 302, 72);
        Joints min = new(-10, -10, -10, -10, -10, -10), max = new(10, 10, 10, 10, 10, 10);
        Assert.Contains("\"ABB\" or \"KUKA\"", Assert.Throws<ArgumentException>(() => RobotModel.FromOpw("x", "Fanuc", p, min, max)).Message);
        Assert.Contains("must be below the maximum", Assert.Throws<ArgumentException>(() => RobotModel.FromOpw("x", "ABB", p, max, min)).Message);
        Assert.Contains("positive lower arm", Assert.Throws<ArgumentException>(() => RobotModel.FromOpw("x", "ABB", p with { C2 = 0 }, min, max)).Message);
    }

    [Fact]
    public void Pose_CompositionAndInverse_AreConsistent()
    {
        var a = new Pose(100, 20, -30, Rotation.FromAxisAngle(new Vector(1, 2, 3), 40));
        var b = new Pose(-5, 60, 7, Rotation.FromAxisAngle(new Vector(0, 1, -1), -70));
        Assert.True((a * a.Inverse()).IsSimilar(Pose.Identity, 1e-9, 1e-9));
        Vector v = new(1, 2, 3);
        Assert.True((a * b).Transform(v).IsSimilar(a.Transform(b.Transform(v)), 1e-9));
        // A quarter turn about Z maps X to Y, then moves.
        var q = new Pose(10, 0, 0, Rotation.FromAxisAngle(Vector.ZAxis, 90));
        Assert.True(q.Transform(new Vector(1, 0, 0)).IsSimilar(new Vector(10, 1, 0), 1e-12));
    }
}
