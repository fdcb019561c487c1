using Machina.Tests.Support;

namespace Machina.Tests.Brands.UR;

/// <summary>
/// A long run of short moves, as a slicer writes them, each drawing the blend warning: the script says so once above the first
/// and once after the run (naming its lines and count), not once per move; every warning still reaches the program's list.
/// </summary>
public class UrWarningRunTests
{
    [Fact]
    public void ShortMovesInARow_OneCommentAboveAndOneAfterTheRun_EveryWarningListed()
    {
        const int moves = 2000;
        RobotProgram program = TestCompile.Program(RobotType.UR, bot =>
        {
            bot.MoveTo(400, 300, 500);
            bot.PrecisionTo(5);
            for (int i = 0; i < moves; i++)
            {
                bot.Move(i % 2 == 0 ? 1 : -1, 0, 0); // 1 mm each: the 5 mm blend overlaps every one
            }
            bot.PrecisionTo(0);
            bot.Move(0, 0, 50);
        }, CompileOptions.Default);
        var lines = program.GetFile("script")!.Lines.ToList();

        var warnings = lines.Where(l => l.StartsWith("  # WARNING: ", StringComparison.Ordinal)).ToList();
        Assert.Equal(3, warnings.Count); // the first move's two (the move before it, and its own), then the run's closing line
        int first = lines.FindIndex(l => l.EndsWith("# [Move [1, 0, 0] mm]", StringComparison.Ordinal)) + 1;
        int last = lines.FindLastIndex(l => l.EndsWith("# [Move [-1, 0, 0] mm]", StringComparison.Ordinal)) + 1;
        Assert.Equal(first + moves - 1, last); // the moves' lines follow each other: no comment in between
        Assert.Equal($"  # WARNING: the same warning for {moves} motions in a row, lines {first} to {last} (written once, above the first)", warnings[2]);
        Assert.Equal(last + 2, lines.IndexOf(warnings[2]) + 1); // after the last move and the comment of PrecisionTo(0), before the next motion
        Assert.StartsWith("  # WARNING: Move(1,0,0); the blend radius of 5 mm is more than half of this motion (1 mm long)", warnings[1], StringComparison.Ordinal);
        // The program's warnings are still one per move (and one for the move before the first).
        Assert.Equal(moves + 1, program.Warnings.Count);
    }

    [Fact]
    public void InstructionFile_RunPastTheWarningsKept_SameScriptAsTheRobotAndEveryWarningCounted()
    {
        // An instruction file's job keeps the first Instructions.MaxWarningsKept warnings and then only counts them; the writer
        // then skips the text of a blend warning that continues a run. The script must not show it: the robot's compile keeps
        // (and formats) every warning, and both write the same bytes.
        int moves = Instructions.MaxWarningsKept + 500;
        var text = new System.Text.StringBuilder("MoveTo(400, 300, 500);\nPrecisionTo(5);\n");
        for (int i = 0; i < moves; i++)
        {
            text.Append(i % 3 == 0 ? "Move(0.5, 0, 0);\n" : i % 3 == 1 ? "Rotate(0, 0, 1, 2);\n" : "Move(-0.25, 0.125, 0);\n");
        }
        text.Append("PrecisionTo(0);\nMove(0, 0, 50);\n");
        string root = Path.Combine(Path.GetTempPath(), "machina-urruns-" + Guid.NewGuid().ToString("N"));
        try
        {
            Directory.CreateDirectory(root);
            string file = Path.Combine(root, "Runs.machina");
            File.WriteAllText(file, text.ToString());
            var bot = Robot.Create("Runs", RobotType.UR);
            bot.Do(text.ToString());
            string expected = Assert.Single(bot.CompileToFolder(Path.Combine(root, "robot"), RobotType.UR));

            FolderCompileResult result = Instructions.CompileToFolder(file, RobotType.UR, Path.Combine(root, "file"));

            Assert.Equal(File.ReadAllBytes(expected), File.ReadAllBytes(Assert.Single(result.Paths)));
            Assert.Equal(moves + 1, result.WarningCount);
            Assert.Equal(bot.Compile(RobotType.UR).Warnings.Count, result.WarningCount);
            Assert.Equal(Instructions.MaxWarningsKept, result.Warnings.Count);
            Assert.Contains($"  # WARNING: the same warning for {moves} motions in a row", File.ReadAllText(result.Paths[0]), StringComparison.Ordinal);
        }
        finally
        {
            Directory.Delete(root, recursive: true);
        }
    }

    [Fact]
    public void WarningRuns_OtherKindBreaksTheRun_LinesCountedInTheFile()
    {
        var file = new ListLineSink();
        var runs = new WarningRuns(file, "# ");
        runs.Add("header");                       // line 1
        runs.Warn("a", "# A1");                   // line 2
        runs.Motion();
        runs.Add("move 1");                       // line 3
        runs.Warn("a", "# A2");
        runs.Motion();
        runs.Add("move 2");                       // line 4
        runs.Add("setting");                      // line 5
        runs.Warn("a", "# A3");
        runs.Motion();
        runs.Add("move 3");                       // line 6
        runs.Warn("b", "# B4");                   // a warning of another kind ends the run: closing line 7, then B4 at 8
        runs.Motion();
        runs.Add("move 4");                       // line 9
        runs.Motion();                            // no warning: a run of one has nothing to close
        runs.Add("move 5");
        runs.EndRun();
        Assert.Equal(
            ["header", "# A1", "move 1", "move 2", "setting", "move 3",
             "# WARNING: the same warning for 3 motions in a row, lines 3 to 6 (written once, above the first)", "# B4", "move 4", "move 5"],
            file.Lines.ToList());
        Assert.Equal(10, runs.LinesWritten);
    }

    /// <summary>The sequence of <see cref="WarningRuns_OtherKindBreaksTheRun_LinesCountedInTheFile"/> with more runs, each warning given by <paramref name="warn"/>.</summary>
    private static (List<string> Lines, int Written) Replay(Action<WarningRuns, string, string> warn)
    {
        var file = new ListLineSink();
        var runs = new WarningRuns(file, "# ");
        runs.Add("header");
        (string Kind, string Line)[][] motions =
        [
            [("a", "# A1"), ("a", "# A1 again")], [("a", "# A2")], [], [("a", "# A3")], [("a", "# A4"), ("b", "# B4")],
            [("b", "# B5")], [("c", "# C6"), ("b", "# B6")], [], [("a", "# A8")],
        ];
        int n = 0;
        foreach ((string Kind, string Line)[] warnings in motions)
        {
            foreach ((string kind, string line) in warnings)
            {
                warn(runs, kind, line);
            }
            runs.Motion();
            runs.Add("move " + ++n);
        }
        runs.EndRun();
        return (file.Lines.ToList(), runs.LinesWritten);
    }

    [Fact]
    public void EndWarnAscii_RunsOfEveryKind_TheLinesOfWarn()
    {
        (List<string> expected, int expectedWritten) = Replay((runs, kind, line) => runs.Warn(kind, line));
        (List<string> lines, int written) = Replay((runs, kind, line) =>
        {
            Span<byte> room = runs.BeginWarnAscii(line.Length);
            System.Text.Encoding.ASCII.GetBytes(line, room);
            runs.EndWarnAscii(kind, line.Length);
        });

        Assert.Equal(expected, lines);
        Assert.Equal(expectedWritten, written);
        Assert.Equal(lines.Count, written);
        Assert.Contains("# WARNING: the same warning for 2 motions in a row, lines 4 to 5 (written once, above the first)", lines);
        Assert.Contains("# WARNING: the same warning for 2 motions in a row, lines 9 to 12 (written once, above the first)", lines);
    }

    [Fact]
    public void Warn_NoRunUnderWay_TheLineReachesTheFileAtOnce()
    {
        var file = new ListLineSink();
        var runs = new WarningRuns(file, "# ");
        runs.Warn("a", "# A1");                   // no run under way: nothing can come before it

        Assert.Equal(["# A1"], file.Lines);
        runs.Motion();
        runs.Add("move 1");
        runs.Warn("b", "# B2");                   // a run of one under way: it may go on, so the line waits for the motion
        Assert.Equal(2, file.Lines.Count);
        runs.Motion();
        Assert.Equal(["# A1", "move 1", "# B2"], file.Lines);
    }
}
