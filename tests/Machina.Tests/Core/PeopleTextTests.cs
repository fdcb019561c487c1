namespace Machina.Tests.Core;

/// <summary>Text written for people (issue 46): one way to write a position, counts that agree with their noun.</summary>
public class PeopleTextTests
{
    [Fact]
    public void Position_PointAndVector_WrittenTheSameWay()
    {
        var position = new Vector(451, 0, 807.1);

        Assert.Equal("[451, 0, 807.1]", position.ToString());
        Assert.Equal("[451, 0, 807.1]", ((Point)position).ToString());
    }

    [Fact]
    public void Counts_OneIsSingular()
    {
        var bot = Robot.Create("Count", "ABB");
        bot.MoveTo(300, 0, 400);
        RobotProgram program = bot.Compile();
        var one = new RobotProgramFile("one", "txt", System.Text.Encoding.UTF8, "//", ["only line"]);

        Assert.Equal("Robot Program File \"one.txt\" with 1 line of code.", one.ToString());
        Assert.EndsWith("with 2 files.", program.ToString(), StringComparison.Ordinal);
    }
}
