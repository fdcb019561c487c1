namespace Machina.Tests.Core;

/// <summary>Compile reads the issued actions without consuming them; ClearProgram starts a new program from the current state.</summary>
public class RobotProgramTests
{
    [Fact]
    public void Compile_Twice_GivesTheSameProgramAndKeepsTheActions()
    {
        var bot = Robot.Create("Prog", RobotType.ABB);
        bot.MoveTo(1, 2, 3);
        bot.SpeedTo(100);

        string first = bot.Compile(RobotType.MACHINA).Files[0].ToText();
        string second = bot.Compile(RobotType.MACHINA).Files[0].ToText();

        Assert.Equal(first, second);
        Assert.Equal(2, bot.GetProgramActions().Count);
        Assert.Equal<RobotAction>([new ActionTranslation(new Vector(1, 2, 3), false), new ActionSpeed(100, false)], Instructions.Parse(first));
    }

    [Fact]
    public void ClearProgram_ThenMore_CompilesOnlyTheNewActionsAndKeepsTheState()
    {
        var bot = Robot.Create("Prog", RobotType.ABB);
        bot.MoveTo(1, 2, 3);
        bot.SpeedTo(100);
        bot.ClearProgram();
        bot.Move(1, 0, 0);

        Assert.Equal<RobotAction>([new ActionTranslation(new Vector(1, 0, 0), true)], Instructions.Parse(bot.Compile(RobotType.MACHINA).Files[0].ToText()));
        Assert.Equal(3, Assert.Single(bot.GetProgramActions()).Id);
        Assert.Equal(new Point(2, 2, 3), bot.GetCurrentPosition());
        Assert.Equal(100, bot.GetCurrentSpeed());
    }
}
