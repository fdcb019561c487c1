namespace Machina.Tests.Core;

/// <summary>SaveProgram checks its folder like CompileToFolder does.</summary>
public class RobotSaveProgramTests
{
    [Theory]
    [InlineData("")]
    [InlineData("   ")]
    public void SaveProgram_BlankFolder_ThrowsInsteadOfWritingIntoTheCurrentDirectory(string folder)
    {
        var bot = Robot.Create("Blank", RobotType.ABB);
        bot.MoveTo(1, 2, 3);
        RobotProgram program = bot.Compile();

        var ex = Assert.Throws<ArgumentException>(() => bot.SaveProgram(program, folder));

        Assert.Equal("folderPath", ex.ParamName);
        Assert.False(Directory.Exists(Path.Combine(folder, "Blank_Program")));
    }

    [Fact]
    public void SaveProgram_NullFolder_Throws()
    {
        var bot = Robot.Create("Blank", RobotType.ABB);

        var ex = Assert.Throws<ArgumentNullException>(() => bot.SaveProgram(bot.Compile(), null!));

        Assert.Equal("folderPath", ex.ParamName);
    }
}
