namespace Machina.Tests.Kinematics;

public class RobotModelSelectionTests
{
    [Fact]
    public void Create_WithModelName_SetsModel()
    {
        Robot bot = Robot.Create("Bot", "UR", "ur5e");
        Assert.Equal("UR5e", bot.Model!.Name);
        Assert.Equal("UR", bot.Model.Brand);
    }

    [Fact]
    public void Create_ModelOfOtherBrand_ThrowsNamingBoth()
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB", "UR5e"));
        Assert.Contains("The model UR UR5e is a UR arm, but this robot's brand is ABB.", ex.Message);
    }

    [Fact]
    public void Create_UnknownModel_ThrowsWithSuggestion()
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB", "IRB 12"));
        Assert.Contains("There is no robot model called \"IRB 12\"", ex.Message);
        Assert.Contains("IRB 120", ex.Message);
    }

    [Fact]
    public void SetModel_OnPrinter_Throws()
    {
        Robot bot = Robot.Create("Printer", "ZMORPH");
        var ex = Assert.Throws<ArgumentException>(() => bot.SetModel("IRB 120"));
        Assert.Contains("3D printer", ex.Message);
        Assert.Null(bot.Model);
    }

    [Fact]
    public void SetModel_HumanRobot_AcceptsAnyBrand()
    {
        Robot bot = Robot.Create("Bot", RobotType.HUMAN);
        bot.SetModel("KR 16");
        Assert.Equal("KUKA", bot.Model!.Brand);
    }

    [Fact]
    public void SetModel_AfterMotion_ThrowsAndKeepsModel()
    {
        Robot bot = Robot.Create("Bot", "ABB");
        bot.SpeedTo(100);
        bot.SetModel("IRB 120");
        bot.AxesTo(0, 0, 0, 0, 30, 0);
        var ex = Assert.Throws<InvalidOperationException>(() => bot.SetModel("IRB 140"));
        Assert.Contains("before the first motion", ex.Message);
        Assert.Equal("IRB 120", bot.Model!.Name);
    }

    [Fact]
    public void Models_ListsCatalogue()
    {
        Assert.Same(RobotModels.All, Robot.Models);
        Assert.Contains(Robot.Models, m => m.Name == "IRB 120");
    }

    [Fact]
    public void Create_CustomModel_Used()
    {
        RobotModel irb = RobotModels.Get("IRB 120");
        RobotModel mine = RobotModel.FromOpw("My arm", "ABB", irb.Opw!.Value, irb.MinJoints, irb.MaxJoints);
        Robot bot = Robot.Create("Bot", RobotType.ABB, mine);
        Assert.Same(mine, bot.Model);
        Assert.Throws<ArgumentException>(() => Robot.Create("Bot", RobotType.UR, mine));
    }

    [Fact]
    public void NoModel_AxesTo_PoseStaysUnknownAndNoWarnings()
    {
        Robot bot = Robot.Create("Bot", "ABB");
        bot.AxesTo(0, 0, 0, 0, 0, 0);
        Assert.Null(bot.Model);
        Assert.Null(bot.GetCurrentPosition());
        Assert.Null(bot.GetCurrentRotation());
        Assert.Throws<ActionRefusedException>(() => bot.Move(0, 0, 10));
        bot.TransformTo(new Vector(5000, 0, 0), Rotation.FlippedAroundY);
        Assert.Null(bot.GetCurrentAxes());
        Assert.Empty(bot.GetWarnings());
        Assert.Empty(bot.Compile().Warnings);
    }
}
