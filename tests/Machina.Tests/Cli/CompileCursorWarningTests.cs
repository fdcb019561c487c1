namespace Machina.Tests.Cli;

/// <summary>
/// Warnings the robot's state raises while the actions are applied (a tool defined again, an extruded length that cannot be
/// computed) reach the program's warnings and the command line's standard error; attaching a tool before the first absolute
/// motion, the usual order, raises none.
/// </summary>
public class CompileCursorWarningTests
{
    private const string Program = """
        DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50);
          DefineTool("pen", 0, 0, 120, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50);
        AttachTool("pen");
        MoveTo(300, 0, 400);
        """;

    [Fact]
    public async Task Compile_CursorWarnings_GoToStandardErrorWithTheirLines()
    {
        using var cli = new CliRunner();
        cli.Write("p.machina", Program);

        CliResult result = await cli.RunAsync("compile", "p.machina", "--brand", "abb", "--out", "out");

        Assert.Equal(0, result.Exit);
        Assert.Equal(
            [
                "p.machina:2:3: warning: DefineTool(\"pen\",0,0,120,1,0,0,0,1,0,0.5,0,0,50); a tool named \"pen\" was already defined; the new definition replaces it.",
            ],
            result.Stderr.Split('\n').Where(l => l.Contains(": warning: ", StringComparison.Ordinal)));
        Assert.Contains("1 warning.", result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public void Compile_ExtrudedLengthUnknown_IsAProgramWarningOnce()
    {
        Robot bot = Robot.Create("Printer", RobotType.ZMORPH);
        bot.MoveTo(100, 100, 10);
        bot.Extrude(true);
        bot.AxesTo(0, 0, 0, 0, 0, 0);

        RobotProgram program = bot.Compile();

        Assert.Equal(["the extruded length could not be computed because the path length of this motion is unknown."],
            program.Warnings.Where(w => w.Instruction == "AxesTo(0,0,0,0,0,0);").Select(w => w.Message).Where(m => m.Contains("extruded", StringComparison.Ordinal)));
    }
}
