namespace Machina.Tests.Kinematics;

public class RobotStateInStepTests
{
    private static readonly RobotModel Irb120 = RobotModels.Get("IRB 120");

    private static void AssertPose(Pose expected, Robot bot)
    {
        Vector p = bot.GetCurrentPosition()!.Value;
        Assert.True(Vector.Distance(expected.Position, p) < 1e-6, $"position {p}, expected {expected.Position}");
        Assert.True(expected.Rotation.IsSimilar(bot.GetCurrentRotation()!.Value, 1e-6), "rotation differs");
    }

    private static void AssertJoints(Joints expected, Joints? actual)
    {
        Assert.NotNull(actual);
        for (int i = 0; i < Joints.Count; i++)
        {
            Assert.Equal(expected[i], actual.Value[i], 6);
        }
    }

    [Fact]
    public void AxesTo_WithModel_PoseIsForwardKinematics()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        var j = new Joints(10, 20, -10, 30, 40, 50);
        bot.AxesTo(j);
        AssertPose(Irb120.Kinematics.Forward(j), bot);
        AssertJoints(j, bot.GetCurrentAxes());
    }

    [Fact]
    public void AxesToThenMove_WithModel_RelativeMoveFromFkPoseAndJointsFollow()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        var j = new Joints(0, 0, 0, 0, 30, 0);
        bot.AxesTo(j);
        bot.Move(0, 0, -50);
        Pose fk = Irb120.Kinematics.Forward(j);
        var expected = new Pose(fk.Position + new Vector(0, 0, -50), fk.Rotation);
        AssertPose(expected, bot);
        Assert.Equal(302 + 72 * Math.Cos(Math.PI / 6), fk.Position.X, 6); // wrist centre at (302, 0, 630), flange 72 mm away, tilted 30° down
        Assert.Equal(630 - 72 * Math.Sin(Math.PI / 6) - 50, bot.GetCurrentPosition()!.Value.Z, 6);
        Joints after = bot.GetCurrentAxes()!.Value;
        Assert.True(Irb120.Kinematics.Forward(after).IsSimilar(expected, 1e-6, 1e-6));
        Assert.True(Math.Abs(after.J5 - 30) < 15, $"the solution closest to the previous joints, got {after}");
    }

    [Fact]
    public void TransformToThenAxes_WithModel_RelativeAxesFromIkJoints()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        var j = new Joints(10, 20, -10, 30, 40, 50);
        Pose target = Irb120.Kinematics.Forward(j);
        bot.TransformTo(target.Position, target.Rotation);
        AssertJoints(j, bot.GetCurrentAxes()); // unknown previous joints: the solution closest to all-zero joints
        bot.Axes(0, 0, 0, 0, 0, 10);
        var next = new Joints(10, 20, -10, 30, 40, 60);
        AssertJoints(next, bot.GetCurrentAxes());
        AssertPose(Irb120.Kinematics.Forward(next), bot);
    }

    [Fact]
    public void AttachTool_WithModel_TcpIsFlangeTimesToolAndJointsSolveTheFlange()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        var j = new Joints(0, 10, 10, 0, 45, 0);
        bot.AxesTo(j);
        bot.DefineTool("pen", new Vector(0, 0, 100), Rotation.Identity);
        bot.AttachTool("pen");
        Pose flange = Irb120.Kinematics.Forward(j);
        var tool = new Pose(new Vector(0, 0, 100), Rotation.Identity);
        AssertPose(flange * tool, bot);
        AssertJoints(j, bot.GetCurrentAxes());

        bot.Move(0, 30, 0);
        Joints moved = bot.GetCurrentAxes()!.Value;
        var expectedTcp = new Pose((flange * tool).Position + new Vector(0, 30, 0), flange.Rotation);
        Assert.True((Irb120.Kinematics.Forward(moved) * tool).IsSimilar(expectedTcp, 1e-6, 1e-6));

        bot.AxesTo(j);
        AssertPose(flange * tool, bot); // FK then the attached tool
        bot.DetachTool();
        AssertPose(flange, bot);
        AssertJoints(j, bot.GetCurrentAxes());
    }

    [Fact]
    public void Unreachable_NonStrict_KeepsPoseJointsUnknownAndWarns()
    {
        Robot bot = Robot.Create("Bot", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 30, 0);
        bot.MoveTo(2000, 0, 300);
        Assert.Equal(new Point(2000, 0, 300), bot.GetCurrentPosition());
        Assert.Null(bot.GetCurrentAxes());
        ProgramWarning w = Assert.Single(bot.GetWarnings());
        Assert.Equal(KinematicIssueKind.Unreachable, w.Kind);
        Assert.Equal(2, w.ActionId);
        Assert.Equal("MoveTo(2000,0,300);", w.Instruction);
        Assert.Contains("out of reach of the ABB IRB 120", w.Message);
    }

    [Fact]
    public void UrModel_AxesToThenMove_StaysInStep()
    {
        RobotModel ur = RobotModels.Get("UR5e");
        Robot bot = Robot.Create("Bot", "UR", "UR5e");
        var j = new Joints(0, -90, 90, -90, -90, 0);
        bot.AxesTo(j);
        bot.Move(50, 0, 0);
        Pose expected = ur.Kinematics.Forward(j);
        expected = new Pose(expected.Position + new Vector(50, 0, 0), expected.Rotation);
        Assert.True(ur.Kinematics.Forward(bot.GetCurrentAxes()!.Value).IsSimilar(expected, 1e-6, 1e-6));
    }
}
