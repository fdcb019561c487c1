namespace Machina.Tests.Brands.Abb;

/// <summary>
/// An instruction file that names nothing that declares (no speed, zone, tool, custom code or IO statement) is compiled to RAPID
/// straight into its module, with the declarations of one motion in the start state written before the instructions; the
/// declarations met while writing are checked at the end, and a text they do not fit (one without motions) is written again.
/// Either way the files are those of a robot that issued the same instructions.
/// </summary>
public sealed class RapidForeseenTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), "machina-foreseen-" + Guid.NewGuid().ToString("N"));

    public RapidForeseenTests() => Directory.CreateDirectory(_root);

    public void Dispose() => Directory.Delete(_root, recursive: true);

    /// <summary>Compiles <paramref name="text"/> from a file and as a robot's program; returns both modules' lines.</summary>
    private (string[] File, string[] Robot) Both(string text)
    {
        string file = Path.Combine(_root, "Prog.machina");
        File.WriteAllText(file, text);
        FolderCompileResult result = Instructions.CompileToFolder(file, RobotType.ABB, Path.Combine(_root, "file"));
        var bot = Robot.Create("Prog", "ABB");
        bot.Do(text);
        IReadOnlyList<string> expected = bot.CompileToFolder(Path.Combine(_root, "robot"));

        Assert.Equal(expected.Select(Path.GetFileName), result.Paths.Select(Path.GetFileName));
        for (int i = 0; i < expected.Count; i++)
        {
            Assert.Equal(File.ReadAllBytes(expected[i]), File.ReadAllBytes(result.Paths[i]));
        }
        Assert.Empty(Directory.GetFiles(Path.Combine(_root, "file"), "*" + FolderProgramOutput.PartialSuffix));
        return (File.ReadAllLines(Path.Combine(_root, "file", "Prog.mod")), File.ReadAllLines(Path.Combine(_root, "robot", "Prog.mod")));
    }

    [Fact]
    public void CompileToFolder_OnlyMovesAndTurns_DeclaresTheStartSpeedAndZoneBeforeMain()
    {
        (string[] mod, _) = Both("MoveTo(300, 0, 500);\nMove(1.5, 0, 0);\nRotate(0, 0, 1, 10);\nMove(0, -2, 0.25);\n");

        int speed = Array.IndexOf(mod, "  CONST speeddata vel20 := [20,20,20,20];");
        int main = Array.IndexOf(mod, "  PROC main()");
        Assert.InRange(speed, 1, main - 1);
        Assert.Equal(4, mod.Count(l => l.StartsWith("    MoveL [[", StringComparison.Ordinal) && l.Contains(", vel20, z5, Tool0\\WObj:=WObj0;", StringComparison.Ordinal)));
        Assert.Equal("    MoveL [[301.5, 0, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;  ! [Move [1.5, 0, 0] mm]", mod[main + 6]);
        Assert.Equal("ENDMODULE", mod[^1]);
    }

    [Fact]
    public void CompileToFolder_NoMotion_WrittenAgainWithoutSpeedOrZone()
    {
        // Nothing declares, so the start state's speed and zone are foreseen; but nothing moves, so the robot declares neither.
        (string[] mod, _) = Both("Wait(100);\nMessage(\"hello\");\n// a note\n");

        Assert.DoesNotContain(mod, line => line.Contains("speeddata", StringComparison.Ordinal));
        Assert.Equal("    WaitTime 0.1;  ! [Wait 100 ms]", mod[Array.IndexOf(mod, "  PROC main()") + 5]);
        Assert.Equal(1, mod.Count(l => l == "MODULE Prog"));
    }

    [Fact]
    public void CompileToFolder_ASpeedNamedOnlyInAComment_SameModule()
    {
        // The word "Speed" in a comment sends the text the other way (a spool): the module is the same.
        Both("MoveTo(300, 0, 500); // Speed stays 20\nMove(1, 0, 0);\n");
    }
}
