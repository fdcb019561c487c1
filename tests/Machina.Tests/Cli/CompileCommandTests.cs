namespace Machina.Tests.Cli;

public class CompileCommandTests
{
    /// <summary>A program that uses most kinds of action: settings, absolute and relative moves, an arc, joints, IO, a tool.</summary>
    internal const string Program = """
        // square with extras
        Message("Hello");
        SpeedTo(100);
        PrecisionTo(2);
        MoveTo(300, -100, 400);
        Move(0, 0, -100);
        Move(150, 0, 0); Move(0, 200, 0);
        Rotate(0, 0, 1, 30);
        ArcMotionTo(375, 0, 360,
                    300, 100, 300);
        Wait(500);
        WriteDigital(1, true);
        MoveTo(300, 100, 450);
        AxesTo(0, 0, 0, 0, 90, 0);
        """;

    public static TheoryData<string> AllBrands => new() { "abb", "ur", "kuka", "zmorph", "marlin", "human", "machina" };

    [Theory]
    [MemberData(nameof(AllBrands))]
    public async Task Compile_EveryBrand_WritesExactlyWhatTheLibraryCompiles(string brand)
    {
        using var cli = new CliRunner();
        cli.Write("square.machina", Program);

        CliResult result = await cli.RunAsync("compile", "square.machina", "--brand", brand, "--out", "out");

        Assert.Equal(0, result.Exit);
        Robot robot = Robot.Create("square", brand);
        robot.Do(Program);
        RobotProgram expected = robot.Compile(robot.Brand);
        Assert.Equal(expected.Files.Select(f => Path.Combine("out", f.FileName)).Order(), result.Lines.Order());
        foreach (RobotProgramFile file in expected.Files)
        {
            Assert.Equal(file.ToText(), File.ReadAllText(cli.PathOf(Path.Combine("out", file.FileName))));
        }
    }

    [Fact]
    public async Task Compile_WithModelAndNoComments_MatchesTheLibrary()
    {
        using var cli = new CliRunner();
        cli.Write("square.machina", Program);

        CliResult result = await cli.RunAsync("compile", "square.machina", "--brand", "abb", "--model", "IRB 120", "--no-comments", "--out", "out", "--name", "Demo");

        Assert.Equal(0, result.Exit);
        Robot robot = Robot.Create("Demo", "ABB", "IRB 120");
        robot.Do(Program);
        RobotProgram expected = robot.Compile(inlineTargets: true, humanComments: false);
        Assert.Equal(expected.GetFile("mod")!.ToText(), File.ReadAllText(cli.PathOf("out/Demo.mod")));
        Assert.DoesNotContain("! [", File.ReadAllText(cli.PathOf("out/Demo.mod")), StringComparison.Ordinal);
    }

    [Fact]
    public async Task Compile_StandardInput_ReadsTheProgramFromIt()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync(["compile", "-", "--brand", "machina", "--out", "out", "--name", "Piped"], "MoveTo(1, 2, 3);\nWait(5);\n", CancellationToken.None);

        Assert.Equal(0, result.Exit);
        string text = File.ReadAllText(cli.PathOf("out/Piped.machina"));
        Assert.EndsWith("MoveTo(1,2,3);\nWait(5);\n", text, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Compile_MalformedValue_ReportsFileLineColumnAndWritesNothing()
    {
        using var cli = new CliRunner();
        cli.Write("bad.machina", "SpeedTo(100);\nMoveTo(1, 2, 3);\nMoveTo(1, 2, x);\n");

        CliResult result = await cli.RunAsync("compile", "bad.machina", "--brand", "abb", "--out", "out");

        Assert.Equal(1, result.Exit);
        Assert.StartsWith("bad.machina:3:14: error: argument 3 of MoveTo must be a number", result.Stderr, StringComparison.Ordinal);
        Assert.False(Directory.Exists(cli.PathOf("out")));
    }

    [Theory]
    // A refused second statement of a line: the column where that statement starts.
    [InlineData("MoveTo(1, 2, 3);\nWait(1); PopSettings();\n", "ur", "p.machina:2:10: error: cannot apply \"PopSettings();\":")]
    [InlineData("MoveTo(1, 2, 3);\nPopSettings();\n", "kuka", "p.machina:2:1: error: cannot apply \"PopSettings();\":")]
    [InlineData("MoveTo(1, 2, 3);\nPopSettings();\n", "marlin", "p.machina:2:1: error: cannot apply \"PopSettings();\":")]
    // A relative move before any position, after a comment, a blank line and an indent.
    [InlineData("// starts relative\n\n   Move(0, 0, 10);\n", "abb", "p.machina:3:4: error: cannot apply \"Move(0,0,10);\":")]
    // A statement still open at the end of the file: reported at the end.
    [InlineData("MoveTo(1, 2, 3);\nMoveTo(1,\n 2,", "abb", "p.machina:3:4: error: MoveTo( is not closed with ')'.")]
    public async Task Compile_RefusedStatement_IsReportedAtItsLineAndColumn(string program, string brand, string error)
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("compile", program, "--brand", brand, "--out", "out");

        Assert.Equal(1, result.Exit);
        Assert.StartsWith(error, result.Stderr, StringComparison.Ordinal);
        Assert.False(Directory.Exists(cli.PathOf("out")), "a failed compile must not leave the folder it created");
    }

    [Fact]
    public async Task Compile_LongProgramWithStatementsAcrossBlocks_KeepsLinesAndOutput()
    {
        using var cli = new CliRunner();
        var lines = new List<string> { "MoveTo(0, 0, 0);" };
        for (int i = 1; i < 700; i++)
        {
            // Every 97th statement spans three lines, so some cross the reader's block boundaries.
            lines.Add(i % 97 == 0 ? $"Move(1,\n  0,\n  0);" : $"Move(0, 0, {i % 3 + 1});");
        }
        string text = string.Join("\n", lines) + "\nMoveTo(1, 2, y);\n";
        int errorLine = text.Split('\n').Length - 1;
        cli.Write("long.machina", text.Replace("\nMoveTo(1, 2, y);\n", "\n", StringComparison.Ordinal));
        cli.Write("bad.machina", text);

        CliResult good = await cli.RunAsync("compile", "long.machina", "--brand", "machina", "--out", "out");
        CliResult bad = await cli.RunAsync("compile", "bad.machina", "--brand", "machina", "--out", "out2");

        Assert.Equal(0, good.Exit);
        Robot robot = Robot.Create("long", RobotType.MACHINA);
        robot.Do(string.Join("\n", lines));
        Assert.Equal(robot.Compile(RobotType.MACHINA).Files[0].ToText(), File.ReadAllText(cli.PathOf("out/long.machina")));
        Assert.Equal(1, bad.Exit);
        Assert.StartsWith($"bad.machina:{errorLine}:14: error:", bad.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Compile_PrinterWarnings_GoToStandardErrorWithTheirLines()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("compile", "MoveTo(100, 100, 10);\nExtrude(true);\nMove(10, 0, 0);\nRotate(0, 0, 1, 45);\n", "--brand", "zmorph", "--out", "out");

        Assert.Equal(0, result.Exit);
        Assert.Contains("p.machina:4:1: warning: Rotate(0,0,1,45);", result.Stderr, StringComparison.Ordinal);
        Assert.Contains("1 warning.", result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Compile_MoreWarningsThanKept_PrintsTheFirstAndCountsTheRest()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("compile", "MoveTo(100, 100, 10);\n" + string.Concat(Enumerable.Repeat("Rotate(0, 0, 1, 1);\n", Instructions.MaxWarningsKept + 5)), "--brand", "zmorph", "--out", "out");

        Assert.Equal(0, result.Exit);
        string[] warnings = result.Stderr.Split('\n').Where(l => l.Contains(": warning: Rotate(", StringComparison.Ordinal)).ToArray();
        Assert.Equal(Instructions.MaxWarningsKept, warnings.Length);
        Assert.StartsWith($"p.machina:{Instructions.MaxWarningsKept + 1}:1: warning:", warnings[^1], StringComparison.Ordinal);
        Assert.Contains("p.machina: and 5 more warnings", result.Stderr, StringComparison.Ordinal);
        Assert.Contains($"{Instructions.MaxWarningsKept + 5} warnings.", result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Compile_UnreachableTargetWithModel_WarnsAtItsLineAndColumn()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("compile", "MoveTo(300, 0, 400);\n  MoveTo(2000, 0, 400);\n", "--brand", "abb", "--model", "IRB 120", "--out", "out");

        Assert.Equal(0, result.Exit);
        Assert.Contains("p.machina:2:3: warning: MoveTo(2000,0,400); Unreachable:", result.Stderr, StringComparison.Ordinal);
        Assert.DoesNotContain("p.machina:1:", result.Stderr, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--brand", "abb", "--model", "UR5e", "is a UR arm")]
    [InlineData("--brand", "marlin", "--model", "UR5e", "3D printer")]
    [InlineData("--brand", "abb", "--model", "IRB 9999", "no robot model called")]
    [InlineData("--brand", "fanuc", "--out", "x", "\"fanuc\" is not a brand")]
    public async Task Compile_WrongBrandOrModel_IsAUsageError(string o1, string v1, string o2, string v2, string message)
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("compile", "MoveTo(1, 2, 3);", o1, v1, o2, v2);

        Assert.Equal(2, result.Exit);
        Assert.Contains(message, result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Compile_MissingFile_SaysWhereItLooked()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("compile", "nothere.machina", "--brand", "abb");

        Assert.Equal(1, result.Exit);
        Assert.Contains("There is no file \"nothere.machina\"", result.Stderr, StringComparison.Ordinal);
    }
}
