using System.Text;
using Machina.Tests.Support;

namespace Machina.Tests.Programs;

/// <summary>
/// <c>Instructions.CompileToFolder</c> reads an instruction file statement by statement and writes the same bytes as a robot
/// that issued the same instructions and compiled to a folder; errors carry their line and column, and leave no file behind.
/// </summary>
public sealed class InstructionFileCompileTests : IDisposable
{
    private static readonly RobotType[] Languages = [RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.ZMORPH, RobotType.MARLIN, RobotType.HUMAN, RobotType.MACHINA];

    private readonly string _root = Path.Combine(Path.GetTempPath(), "machina-filecompile-" + Guid.NewGuid().ToString("N"));

    public InstructionFileCompileTests() => Directory.CreateDirectory(_root);

    public void Dispose() => Directory.Delete(_root, recursive: true);

    /// <summary>Custom declarations, accelerations, settings stacks, tools, IO, arcs, extrusion, statements over several lines and comments.</summary>
    private const string Mixed = """
        // A program that uses most instructions.
        CustomCode("VAR num counter := 0;", true);
        SpeedTo(120); AccelerationTo(800);
        PrecisionTo(2)
        MoveTo(300, 0, 500);
        DefineTool("pen", 0, 0, 100,
                   1, 0, 0,
                   0, 1, 0,
                   0.5, 0, 0, 20); // mass and centre of gravity
        AttachTool("pen");
        PushSettings(); SpeedTo(40); Move(10, 0, 0); PopSettings();
        Move(0,
             10,   // y
             0.25);
        Rotate(0, 0, 1, 30);
        ArcMotionTo(320, 20, 500, 340, 0, 500);
        WriteDigital(1, true); WriteAnalog(2, 0.5);
        Message("say \"hi\"; // not a comment");
        Wait(500);
        TemperatureTo(210, "extruder", false);
        Extrude(true); ExtrusionRateTo(0.8);
        Move(5, 5, 0);
        Extrude(false);
        CustomCode("counter := counter + 1;");
        DetachTool();
        AxesTo(0, 0, 0, 0, 90, 0);
        """;

    public static IEnumerable<object[]> Cases()
    {
        foreach (RobotType language in Languages)
        {
            foreach (string program in ReferencePrograms.All.Keys.Append("Mixed"))
            {
                yield return [language, program, true];
            }
            yield return [language, "Mixed", false];
        }
    }

    private static string Text(string program)
    {
        if (program == "Mixed")
        {
            return Mixed;
        }
        Robot bot = ReferencePrograms.Issue(program, RobotType.ABB);
        return string.Join("\n", bot.GetProgramActions().Select(a => a.ToInstruction())) + "\n";
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void CompileToFolder_InstructionFile_SameBytesAndWarningsAsRobot(RobotType language, string program, bool inline)
    {
        string text = Text(program);
        var options = new CompileOptions { InlineTargets = inline };
        var bot = Robot.Create(program, language);
        bot.Do(text);
        string expectedFolder = Path.Combine(_root, "robot");
        IReadOnlyList<string> expected = bot.CompileToFolder(expectedFolder, language, options);
        RobotProgram inMemory = bot.Compile(language, options);
        string file = Path.Combine(_root, program + ".machina");
        File.WriteAllText(file, text);

        FolderCompileResult result = Instructions.CompileToFolder(file, language, Path.Combine(_root, "file"), options);

        Assert.Equal(expected.Select(Path.GetFileName), result.Paths.Select(Path.GetFileName));
        for (int i = 0; i < expected.Count; i++)
        {
            Assert.Equal(File.ReadAllBytes(expected[i]), File.ReadAllBytes(result.Paths[i]));
        }
        Assert.Equal(inMemory.Warnings.Select(w => (w.ActionId, w.Instruction, w.Message)), result.Warnings.Select(w => (w.ActionId, w.Instruction, w.Message)));
        Assert.Equal(bot.GetProgramActions().Count, result.ActionCount);
        Assert.Equal(program, result.ProgramName);
        Assert.Empty(Directory.GetFiles(Path.Combine(_root, "file"), "*" + FolderProgramOutput.PartialSuffix));
    }

    [Fact]
    public void CompileToFolder_OverALongerProgramAndALeftOverPartialFile_ExactlyTheNewBytes()
    {
        // New files are created without being emptied, existing ones are emptied: either way nothing of an older, longer file
        // may remain at the end, neither of the program written before nor of a ".partial" file a killed compile left.
        string file = Path.Combine(_root, "short.machina");
        File.WriteAllText(file, "MoveTo(300, 0, 400);\nMove(0, 10, 0);\n");
        string folder = Path.Combine(_root, "over");
        FolderCompileResult first = Instructions.CompileToFolder(file, RobotType.UR, folder);
        byte[] expected = File.ReadAllBytes(Assert.Single(first.Paths));
        string script = first.Paths[0];
        File.WriteAllText(script, new string('#', 50_000));
        File.WriteAllText(script + FolderProgramOutput.PartialSuffix, new string('%', 50_000));

        FolderCompileResult again = Instructions.CompileToFolder(file, RobotType.UR, folder);

        Assert.Equal(script, Assert.Single(again.Paths));
        Assert.Equal(expected, File.ReadAllBytes(script));
        Assert.Contains("movep(p[0.3,0.01,0.4,", File.ReadAllText(script), StringComparison.Ordinal);
        Assert.False(File.Exists(script + FolderProgramOutput.PartialSuffix));
    }

    [Fact]
    public void CompileToFolder_Warning_CarriesLineAndColumnOfItsStatement()
    {
        string file = Path.Combine(_root, "print.machina");
        File.WriteAllText(file, "MoveTo(100, 0, 10);\n\n// turn\nMove(1, 0, 0); Rotate(0, 0, 1, 90);\n");

        FolderCompileResult result = Instructions.CompileToFolder(file, RobotType.MARLIN, Path.Combine(_root, "out"));

        ProgramWarning warning = Assert.Single(result.Warnings);
        Assert.Equal(3, warning.ActionId);
        Assert.Equal((4, 16), (warning.Line, warning.Column));
        Assert.StartsWith("Rotate(", warning.Instruction, StringComparison.Ordinal);
    }

    [Fact]
    public void CompileToFolder_WithModel_WarnsOfUnreachableTargetsAsARobotOfThatModel()
    {
        string file = Path.Combine(_root, "far.machina");
        const string Program = "MoveTo(300, 0, 400);\n  MoveTo(2000, 0, 400);\n";
        File.WriteAllText(file, Program);
        RobotModel model = RobotModels.Get("IRB 120");

        FolderCompileResult withModel = Instructions.CompileToFolder(file, RobotType.ABB, Path.Combine(_root, "model"), model: model);
        FolderCompileResult without = Instructions.CompileToFolder(file, RobotType.ABB, Path.Combine(_root, "none"));

        ProgramWarning warning = Assert.Single(withModel.Warnings);
        Assert.Equal((2, 2, 3, KinematicIssueKind.Unreachable), (warning.ActionId, warning.Line, warning.Column, warning.Kind));
        Assert.Equal(0, without.WarningCount);
        Robot robot = Robot.Create("far", RobotType.ABB, model);
        robot.Do(Program);
        Assert.Equal(robot.Compile().Files[0].ToText(), File.ReadAllText(withModel.Paths[0]));
    }

    [Fact]
    public void CompileToFolder_ManyWarnings_KeepsTheFirstAndCountsAll()
    {
        string file = Path.Combine(_root, "rotations.machina");
        var text = new StringBuilder("MoveTo(100, 0, 10);\n");
        for (int i = 0; i < Instructions.MaxWarningsKept + 200; i++)
        {
            text.Append("Rotate(0, 0, 1, 1);\n");
        }
        File.WriteAllText(file, text.ToString());

        FolderCompileResult result = Instructions.CompileToFolder(file, RobotType.ZMORPH, Path.Combine(_root, "out"));

        Assert.Equal(Instructions.MaxWarningsKept + 200, result.WarningCount);
        Assert.Equal(Instructions.MaxWarningsKept, result.Warnings.Count);
        Assert.Equal((Instructions.MaxWarningsKept + 1, 2, Instructions.MaxWarningsKept + 1), (result.Warnings[^1].ActionId, result.Warnings[0].Line, result.Warnings[^1].Line));
    }

    [Fact]
    public void CompileToFolder_TextReader_SameBytesAsFile()
    {
        string file = Path.Combine(_root, "Mixed.machina");
        File.WriteAllText(file, Mixed);
        FolderCompileResult fromFile = Instructions.CompileToFolder(file, RobotType.KUKA, Path.Combine(_root, "a"));

        using var reader = new StringReader(Mixed);
        FolderCompileResult fromReader = Instructions.CompileToFolder(reader, RobotType.KUKA, Path.Combine(_root, "b"), programName: "Mixed", newLine: "\r\n");

        Assert.Equal(fromFile.Paths.Select(Path.GetFileName), fromReader.Paths.Select(Path.GetFileName));
        string expected = File.ReadAllText(fromFile.Paths[0]).Replace("\n", "\r\n", StringComparison.Ordinal);
        Assert.Equal(expected, File.ReadAllText(fromReader.Paths[0]));
    }

    [Fact]
    public void CompileToFolder_ErrorFarIntoTheFile_ReportsLineAndColumnAndKeepsEarlierProgram()
    {
        string folder = Path.Combine(_root, "out");
        string file = Path.Combine(_root, "Long.machina");
        var text = new StringBuilder("MoveTo(300, 0, 500);\n");
        for (int i = 0; i < 5000; i++)
        {
            text.Append("Move(1, 0, 0);\n");
        }
        File.WriteAllText(file, text.ToString());
        FolderCompileResult good = Instructions.CompileToFolder(file, RobotType.ABB, folder);
        byte[] before = File.ReadAllBytes(good.Paths[1]);
        text.Append("Move(1, 0,\n   0, 0 x);\n"); // four arguments: the error is at the statement, line 5002
        File.WriteAllText(file, text.ToString());

        var error = Assert.Throws<InstructionParseException>(() => Instructions.CompileToFolder(file, RobotType.ABB, folder));

        var expected = Assert.Throws<InstructionParseException>(() => Instructions.Parse(text.ToString()));
        Assert.Equal(5002, error.Line);
        Assert.Equal((expected.Line, expected.Column, expected.Message), (error.Line, error.Column, error.Message));
        Assert.Equal(before, File.ReadAllBytes(good.Paths[1]));
        Assert.Equal(2, Directory.GetFiles(folder).Length);
    }

    [Fact]
    public void CompileToFolder_ActionThatCannotApply_ThrowsWithItsPosition()
    {
        string file = Path.Combine(_root, "Relative.machina");
        File.WriteAllText(file, "SpeedTo(10);\n  Wait(1); Move(10, 0, 0);\n");

        var error = Assert.Throws<InstructionParseException>(() => Instructions.CompileToFolder(file, RobotType.UR, Path.Combine(_root, "out")));

        Assert.Equal((2, 12), (error.Line, error.Column));
        Assert.Contains("cannot apply \"Move(10,0,0);\"", error.Message, StringComparison.Ordinal);
        Assert.False(Directory.Exists(Path.Combine(_root, "out")) && Directory.GetFiles(Path.Combine(_root, "out")).Length > 0);
    }

    /// <summary>
    /// Values a robot language cannot hold (a speed of 1E+300 mm/s: KRL's $VEL.CP with 300 digits; a wait of 292 million years)
    /// stop the compilation with the statement's position, as online refuses them at issue time; no file is written.
    /// </summary>
    [Theory]
    [InlineData(RobotType.ABB, "SpeedTo(1e300);", "the speed would become 1E+300 mm/s; settings are refused beyond 1,000,000 mm/s")]
    [InlineData(RobotType.KUKA, "SpeedTo(1e300);", "the speed would become 1E+300 mm/s; settings are refused beyond 1,000,000 mm/s")]
    [InlineData(RobotType.UR, "DefineTool(\"t\", 0,0,100, 1,0,0, 0,1,0, 1e300, 0,0,50);", "tool \"t\" would weigh 1E+300 kg; tool weights are refused beyond 1,000,000 kg")]
    [InlineData(RobotType.ABB, "WriteAnalog(\"AO_1\", 1e300);", "the analog output AO_1 would be set to 1E+300; analog values are refused beyond ±1,000,000")]
    [InlineData(RobotType.UR, "Wait(9223372036854775807);", "a wait of 9223372036854775807 ms is refused: waits are limited to 1,000,000,000 ms")]
    [InlineData(RobotType.MARLIN, "TemperatureTo(1e300, \"bed\");", "the Bed temperature would become 1E+300 C; settings are refused beyond 1,000,000 C")]
    [InlineData(RobotType.KUKA, "AccelerationTo(2e6);", "the acceleration would become 2000000 mm/s^2; settings are refused beyond 1,000,000 mm/s^2")]
    public void CompileToFolder_ValueNoLanguageHolds_ThrowsWithItsPosition(RobotType language, string statement, string reason)
    {
        string file = Path.Combine(_root, "Huge.machina");
        File.WriteAllText(file, "MoveTo(300, 0, 400);\n  " + statement + "\nMoveTo(300, 10, 400);\n");
        string folder = Path.Combine(_root, "out");

        var error = Assert.Throws<InstructionParseException>(() => Instructions.CompileToFolder(file, language, folder));

        Assert.Equal((2, 3), (error.Line, error.Column));
        Assert.Contains(reason, error.Message, StringComparison.Ordinal);
        Assert.False(Directory.Exists(folder) && Directory.GetFiles(folder).Length > 0);
    }

    [Fact]
    public void CompileToFolder_BadArguments_ThrowArgumentExceptions()
    {
        string file = Path.Combine(_root, "a.machina");
        File.WriteAllText(file, "MoveTo(1, 2, 3);");
        Assert.Throws<FileNotFoundException>(() => Instructions.CompileToFolder(Path.Combine(_root, "missing.machina"), RobotType.ABB, _root));
        Assert.Throws<ArgumentException>(() => Instructions.CompileToFolder(file, RobotType.ABB, " "));
        Assert.Throws<ArgumentException>(() => Instructions.CompileToFolder(file, RobotType.ABB, _root, newLine: "\r"));
        Assert.Throws<ArgumentException>(() => Instructions.CompileToFolder(file, (RobotType)99, _root));
    }

    [Fact]
    public void CompileToFolder_Cancelled_ThrowsAndLeavesNoFile()
    {
        string file = Path.Combine(_root, "c.machina");
        File.WriteAllText(file, "MoveTo(1, 2, 3);");
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();

        Assert.ThrowsAny<OperationCanceledException>(() => Instructions.CompileToFolder(file, RobotType.ABB, Path.Combine(_root, "out"), cancellationToken: cancelled.Token));

        Assert.False(Directory.Exists(Path.Combine(_root, "out")) && Directory.GetFiles(Path.Combine(_root, "out")).Length > 0);
    }

    [Fact]
    public void CompileToFolder_AFolderHasTheNameOfAFile_NothingOfTheCompileRemains()
    {
        string file = Path.Combine(_root, "square.machina");
        File.WriteAllText(file, "MoveTo(300, 0, 500);\nMove(0, 100, 0);\n");
        string folder = Path.Combine(_root, "out");
        Directory.CreateDirectory(Path.Combine(folder, "square.mod"));

        var error = Assert.Throws<IOException>(() => Instructions.CompileToFolder(file, RobotType.ABB, folder));

        Assert.Equal($"\"{Path.Combine(folder, "square.mod")}\" is a folder; the program cannot be written under that name.", error.Message);
        Assert.Equal(["square.mod"], Directory.GetFileSystemEntries(folder).Select(Path.GetFileName)); // no square.pgf, no .partial
    }

    [Fact]
    public void CompileToFolder_FileTruncatedWhileCompiled_RefusedAndNothingWritten()
    {
        string file = Path.Combine(_root, "big.machina");
        File.WriteAllText(file, "MoveTo(300, 0, 500);\n" + string.Concat(Enumerable.Repeat("Move(1, 0, 0);\n", 1000)));
        long length = new FileInfo(file).Length;
        string folder = Path.Combine(_root, "out");
        int opened = 0;
        TextReader Open()
        {
            if (++opened == 1)
            {
                using (var stream = new FileStream(file, FileMode.Open, FileAccess.Write))
                {
                    stream.SetLength(36); // another program cuts the file as it is read, after a whole line
                }
                File.SetLastWriteTimeUtc(file, File.GetLastWriteTimeUtc(file).AddSeconds(1)); // a coarse clock would not see it otherwise
            }
            return new StreamReader(file);
        }

        var error = Assert.Throws<IOException>(() => Instructions.CompileFileToFolder(file, Open, RobotType.ABB, folder, null, "big", "\n", null, CancellationToken.None));

        Assert.Equal($"The instruction file \"{file}\" changed while it was compiled ({length} bytes before, 36 bytes after); nothing was written. " +
            "Compile it again once it is complete.", error.Message);
        Assert.False(Directory.Exists(folder));
    }
}
