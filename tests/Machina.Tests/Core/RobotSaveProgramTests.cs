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

    /// <summary>A path whose parent is a file: every way of saving there fails with the same disk error.</summary>
    private static string PathUnderAFile()
    {
        string file = Path.Combine(Path.GetTempPath(), "machina-not-a-folder-" + Guid.NewGuid().ToString("N"));
        File.WriteAllText(file, "x");
        return file;
    }

    [Fact]
    public void SaveProgram_DiskRefuses_ThrowsLikeSaveToFolderAndCompileToFolder()
    {
        string file = PathUnderAFile();
        try
        {
            var bot = Robot.Create("Disk", RobotType.ABB);
            bot.MoveTo(1, 2, 3);
            var logged = new List<string>();
            bot.Logger.Logged += (_, e) => logged.Add(e.Message);
            RobotProgram program = bot.Compile();

            Assert.ThrowsAny<IOException>(() => bot.SaveProgram(program, file));
            Assert.ThrowsAny<IOException>(() => program.SaveToFolder(Path.Combine(file, "sub")));
            Assert.ThrowsAny<IOException>(() => bot.CompileToFolder(Path.Combine(file, "sub")));
            Assert.Contains(logged, m => m.StartsWith("Could not save the program to", StringComparison.Ordinal));
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Theory]
    [InlineData(RobotType.ABB, "Main.mod")]
    [InlineData(RobotType.KUKA, "Main.src")]
    [InlineData(RobotType.UR, "Main.script")]
    [InlineData(RobotType.MARLIN, "Main.gcode")]
    [InlineData(RobotType.HUMAN, "Main.txt")]
    public void MainFile_EveryBrand_IsTheFileWithTheInstructions(RobotType brand, string expected)
    {
        var bot = Robot.Create("Main", brand);
        bot.MoveTo(300, 0, 400);

        Assert.Equal(expected, bot.Compile().MainFile.FileName);
        Assert.Equal("Main.src", bot.Compile(RobotType.KUKA, new CompileOptions { InlineTargets = false }).MainFile.FileName);
    }
}
