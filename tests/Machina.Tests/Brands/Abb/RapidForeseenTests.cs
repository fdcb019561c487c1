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

    [Fact]
    public void CompileToFolder_PlainSpeedTos_DeclaresTheStartSpeedThenEachSpeedSet()
    {
        (string[] mod, _) = Both("MoveTo(300, 0, 500);\nSpeedTo(50);\nMove(1, 0, 0);\nSpeedTo(60.5);\nMove(0, 1, 0);\nSpeedTo(50);\nMove(0, 0, 1);\n");

        int main = Array.IndexOf(mod, "  PROC main()");
        int[] speeds = [.. new[] { "vel20", "vel50", "vel60_5" }.Select(name => Array.FindIndex(mod, l => l.StartsWith("  CONST speeddata " + name + " :=", StringComparison.Ordinal)))];
        Assert.True(speeds[0] > 0 && speeds[0] < speeds[1] && speeds[1] < speeds[2] && speeds[2] < main, string.Join(",", speeds));
        Assert.Equal(2, mod.Count(l => l.Contains(", vel50, z5, Tool0", StringComparison.Ordinal)));
    }

    [Theory]
    [InlineData("SpeedTo(40);\nMoveTo(300, 0, 500);\nMove(1, 0, 0);\n")] // the start speed never moves
    [InlineData("// first\nSpeedTo(40);\nMoveTo(300, 0, 500);\n")] // the guess says the start speed moves: it does not
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo(40);\nSpeedTo(30);\nMove(1, 0, 0);\n")] // a speed set that nothing moves at
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo(40);\nMove(1, 0, 0);\nSpeedTo(70);\n")] // a last speed that nothing moves at
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo(4e1);\nMove(1, 0, 0);\n")]
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo( 40 );\nMove(1, 0, 0);\n")]
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo(0.0004);\nMove(1, 0, 0);\nSpeedTo(0.0001);\nMove(1, 0, 0);\n")] // two speeds written alike
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo(40);\nMove(1, 0, 0);\nSpeed(10);\nMove(1, 0, 0);\n")] // a relative change: not scanned
    [InlineData("MoveTo(300, 0, 500);\nSpeedTo(40.0000000000000000000000000000000000000000000000000000000001);\nMove(1, 0, 0);\n")] // too long to scan
    [InlineData("MoveTo(300, 0, 500); // SpeedTo(90)\nMove(1, 0, 0);\n")] // named only in a comment: the guess is wrong
    [InlineData("Wait(100);\nSpeedTo(40);\nMessage(\"SpeedTo(80)\");\n")] // no motion at all
    public void CompileToFolder_SpeedTosTheGuessGetsWrong_SameModuleAsTheRobot(string text) => Both(text);

    [Fact]
    public void CompileToFolder_ManySpeedTosAcrossScanBlocks_SameModuleAsTheRobot()
    {
        // 20,000 lines cross the scan's 64 KB blocks at every place of a statement: each SpeedTo is still read whole.
        var text = new System.Text.StringBuilder("MoveTo(300, 0, 500);\n");
        for (int i = 0; i < 20_000; i++)
        {
            text.Append(i % 37 == 0 ? $"SpeedTo({10 + i % 11 * 5});\n" : i % 2 == 0 ? "Move(1.5, -2.25, 0.125);\n" : "Move(-1.5, 2, 0.5);\n");
        }
        (string[] mod, _) = Both(text.ToString()); // 10, 15, … 60 mm/s (20 is also the start speed)

        Assert.Equal(11, mod.Count(l => l.StartsWith("  CONST speeddata ", StringComparison.Ordinal)));
    }
}
