namespace Machina.Tests.State;

/// <summary>A relative move that cannot be applied says the real reason (issue 46): after AxesTo without a model, the pose is unknown.</summary>
public class PoseUnknownReasonTests
{
    [Fact]
    public void Move_AfterAxesToWithoutAModel_SaysThePoseNeedsAModel()
    {
        var bot = Robot.Create("R", RobotType.ABB);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.Move(0, 0, 50));

        Assert.Equal("Cannot apply \"Move(0,0,50);\": the position of the tool after a joint motion (AxesTo) is not known without a robot model; "
            + "give the robot its model (Robot.Create(name, brand, model), or --model on the command line) or use MoveTo or TransformTo "
            + "before relative motions.", ex.Message);
    }

    [Fact]
    public void Move_AfterAxesToWithAModel_IsApplied()
    {
        var bot = Robot.Create("R", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        Assert.True(bot.Move(0, 0, 50));
    }
}
