namespace Machina.Tests.State;

/// <summary>With a model, a joint move has a known pose (forward kinematics): in the issue cursor, in Do() and offline.</summary>
public sealed class JointMovePoseTests
{
    [Fact]
    public void AxesTo_WithModel_KnowsThePose_AndARelativeMoveFollows()
    {
        var bot = Robot.Create("Arm", "ABB", "IRB 120");
        Pose flange = RobotModels.Get("IRB 120").Kinematics.Forward(new Joints(0, 0, 0, 0, 90, 0));

        bot.AxesTo(0, 0, 0, 0, 90, 0);

        Assert.True(flange.Position.IsSimilar(new Vector(302, 0, 558), 1e-6), $"IRB 120 flange at {flange.Position}");
        Assert.Equal(flange.Position, bot.GetCurrentPosition());
        Assert.Equal(flange.Rotation, bot.GetCurrentRotation());
        RobotState issued = bot.GetIssuedState();
        Assert.Equal(flange.Position, issued.Position);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), issued.Axes);

        bot.Do("Move(0, 0, -100);");

        Vector after = bot.GetCurrentPosition()!.Value;
        Assert.True(after.IsSimilar(new Vector(302, 0, 458), 1e-6), $"after Move(0, 0, -100): {after}");
        Assert.NotNull(bot.GetCurrentAxes());
    }

    [Fact]
    public void AxesTo_WithoutModel_LeavesThePoseUnknown_AndSaysSoForARelativeMove()
    {
        var bot = Robot.Create("Arm", "ABB");

        bot.AxesTo(0, 0, 0, 0, 90, 0);

        Assert.Null(bot.GetCurrentPosition());
        var ex = Assert.Throws<ActionRefusedException>(() => bot.Move(0, 0, -100));
        Assert.Contains("the position of the tool after a joint motion (AxesTo) is not known without a robot model", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Compile_WithModel_WritesTheMoveAfterAJointMoveAtItsForwardKinematicsPose()
    {
        var bot = Robot.Create("Arm", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.Move(0, 0, -100);

        string rapid = bot.Compile().MainFile.ToText();

        Assert.Contains("MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9,9E9,9E9,9E9,9E9,9E9]]", rapid, StringComparison.Ordinal);
        Assert.Contains("MoveL [[302, 0, 458], ", rapid, StringComparison.Ordinal);
    }
}
