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
}
