namespace Machina.Tests.Brands.Abb;

/// <summary>
/// The RAPID compiler writes the instructions in one pass while it gathers the declarations, with provisional names; when a
/// name turns out to collide it compiles again in two passes. Either way the module is the same.
/// </summary>
public class RapidOnePassTests
{
    private static Robot CollidingProgram()
    {
        var bot = Robot.Create("Collide", "ABB");
        // The tool is met before the speed, so one pass would name it "vel100"; the declarations name speeds first.
        bot.DefineTool("vel100", new Vector(0, 0, 100), new Orientation(1, 0, 0, 0, 1, 0), 1, new Vector(0, 0, 50));
        bot.AttachTool("vel100");
        bot.SpeedTo(100);
        bot.MoveTo(300, 0, 500);
        // Attached but never moved with: not declared, so its attach line keeps its own name and raises no warning.
        bot.DefineTool("unused", new Vector(0, 0, 10), new Orientation(1, 0, 0, 0, 1, 0), 1, new Vector(0, 0, 5));
        bot.AttachTool("unused");
        bot.DetachTool();
        bot.Move(10, 0, 0);
        return bot;
    }

    [Fact]
    public void Compile_NamesCollide_DeclarationsAndUsesAgree()
    {
        RobotProgram program = CollidingProgram().Compile();
        string[] mod = program.Files.Single(f => f.Extension == "mod").ToText().Split('\n');

        Assert.Contains("  PERS tooldata vel100_2 := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];", mod);
        Assert.Contains("  CONST speeddata vel100 := [100,100,100,100];", mod);
        Assert.Contains("    ! Tool \"vel100_2\" attached  ! [Attach tool \"vel100\" to robot flange.]", mod);
        Assert.Contains("    MoveL [[300, 0, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, vel100_2\\WObj:=WObj0;  ! [Move to [300, 0, 500] mm]", mod);
        Assert.Contains("    ! Tool \"unused\" attached  ! [Attach tool \"unused\" to robot flange.]", mod);
        Assert.DoesNotContain(mod, line => line.Contains("tooldata unused"));
        ProgramWarning warning = Assert.Single(program.Warnings);
        Assert.Equal(2, warning.ActionId);
        Assert.Contains("declared as \"vel100_2\"", warning.Message);
    }

    [Fact]
    public void CompileToFolder_NamesCollide_SameFileAsInMemory()
    {
        Robot bot = CollidingProgram();
        string folder = Path.Combine(Path.GetTempPath(), "machina-onepass-" + Guid.NewGuid().ToString("N"));
        try
        {
            bot.CompileToFolder(folder);
            string expected = bot.Compile().Files.Single(f => f.Extension == "mod").ToText();
            Assert.Equal(expected, File.ReadAllText(Path.Combine(folder, "Collide.mod")));
            Assert.Equal(["Collide.mod", "Collide.pgf"], Directory.GetFiles(folder).Select(Path.GetFileName).Order());
        }
        finally
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        }
    }

    [Fact]
    public void CompileToFolder_LongProgram_InstructionsAfterDeclarationsInOrder()
    {
        var bot = Robot.Create("Long", "ABB");
        bot.MoveTo(300, 0, 500);
        for (int i = 0; i < 20_000; i++)
        {
            bot.SpeedTo(10 + i % 3);
            bot.Move(i % 2 == 0 ? 1 : -1, 0, 0);
        }
        string folder = Path.Combine(Path.GetTempPath(), "machina-onepass-" + Guid.NewGuid().ToString("N"));
        try
        {
            bot.CompileToFolder(folder);
            string[] lines = File.ReadAllLines(Path.Combine(folder, "Long.mod"));
            string expected = bot.Compile().Files.Single(f => f.Extension == "mod").ToText();

            Assert.Equal(expected, File.ReadAllText(Path.Combine(folder, "Long.mod")));
            int declaration = Array.IndexOf(lines, "  CONST speeddata vel12 := [12,12,12,12];");
            int main = Array.IndexOf(lines, "  PROC main()");
            Assert.InRange(declaration, 1, main - 1);
            Assert.Equal(20_001, lines.Count(l => l.StartsWith("    MoveL ", StringComparison.Ordinal)));
            Assert.Equal("ENDMODULE", lines[^1]);
        }
        finally
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        }
    }
}
