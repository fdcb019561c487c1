using System.Globalization;
using Machina.Tests.Support;

namespace Machina.Tests.Brands.UR;

public class UrScriptCompilerTests
{
    private static RobotProgram Compile(Action<Robot> issue, CompileOptions? options = null, string name = "Demo") =>
        TestCompile.Program(RobotType.UR, issue, options, name);

    /// <summary>The lines inside the program function, without the blank lines that frame them.</summary>
    private static List<string> Body(RobotProgram program)
    {
        var lines = program.GetFile("script")!.Lines.ToList();
        int start = lines.FindIndex(l => l.StartsWith("def ", StringComparison.Ordinal)) + 2;
        int end = lines.LastIndexOf("end") - 1;
        return lines.GetRange(start, end - start);
    }

    private static void Start(Robot bot) => bot.MoveTo(400, 300, 500);

    [Fact]
    public void Emit_File_DefinesAndCallsTheProgramFunction()
    {
        RobotProgram p = Compile(Start);
        RobotProgramFile file = Assert.Single(p.Files);
        Assert.Equal("Demo.script", file.FileName);
        var lines = file.Lines.ToList();
        Assert.Contains("def Demo():", lines);
        Assert.Equal(["end", "", "Demo()"], lines.TakeLast(3));
        Assert.All(lines.TakeWhile(l => l.Length > 0), l => Assert.StartsWith("# ", l));
    }

    [Fact]
    public void Emit_LinearMove_WritesMovepInMetresAndRadians()
    {
        Assert.Equal(["  movep(p[0.4,0.3,0.5,0,3.141593,0], v=0.02, r=0.005)"], Body(Compile(Start)));
    }

    [Fact]
    public void Emit_MovesOfEveryKind_LinesAsTheBuilderWroteThem()
    {
        // Moves go through one reused array (UrMoveLine), rotations and coordinates too large for its digits through the
        // builder; the lines here are the builder's, written before the array existed: short and long decimals, tiny and
        // negative numbers, joint motion, changed settings, a turn in between, a blend warning, and the largest coordinate allowed (coordinates beyond 1 km are refused).
        RobotProgram program = Compile(bot =>
        {
            Start(bot);
            bot.Move(0.0004, -7.25, 1e-7);
            bot.Move(12.3456789, 0, -0.001);
            bot.Rotate(0, 0, 1, 30);
            bot.Move(1, 2, 3);
            bot.MotionMode("joint");
            bot.SpeedTo(45);
            bot.MoveTo(-1.5, 250.125, 600);
            bot.MotionMode("linear");
            bot.PrecisionTo(0);
            bot.MoveTo(999_999.9995, 0, 600);
        }, CompileOptions.Default);
        // The turn and the move after it draw the same warning: one comment after them names their lines in the file.
        var file = program.GetFile("script")!.Lines.ToList();
        int first = file.FindIndex(l => l.EndsWith("# [Rotate 30 deg around [0, 0, 1]]", StringComparison.Ordinal)) + 1;
        int last = file.FindIndex(l => l.EndsWith("# [Move [1, 2, 3] mm]", StringComparison.Ordinal)) + 1;
        Assert.Equal(first + 1, last);
        Assert.Equal(ExpectedMoves.Select(l => l.Replace("LINES", $"{first} to {last}", StringComparison.Ordinal)), Body(program));
    }

    private static readonly string[] ExpectedMoves =
    [
        "  movep(p[0.4,0.3,0.5,0,3.141593,0], v=0.02, r=0.005)  # [Move to [400, 300, 500] mm]",
        "  # WARNING: MoveTo(400,300,500); the blend radius of 5 mm is more than half of the next motion (7.25 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(3.625) or less around short motions.",
        "  # WARNING: Move(0.0004,-7.25,1E-07); the blend radius of 5 mm is more than half of this motion (7.25 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(3.625) or less around short motions.",
        "  movep(p[0.4,0.29275,0.5,0,3.141593,0], v=0.02, r=0.005)  # [Move [0, -7.25, 0] mm]",
        "  movep(p[0.412346,0.29275,0.499999,0,3.141593,0], v=0.02, r=0.005)  # [Move [12.346, 0, -0.001] mm]",
        "  # WARNING: Move(12.3456789,0,-0.001); the blend radius of 5 mm is more than half of the next motion (0 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(0) or less around short motions.",
        "  # WARNING: Rotate(0,0,1,30); the blend radius of 5 mm is more than half of this motion (0 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(0) or less around short motions.",
        "  movep(p[0.412346,0.29275,0.499999,-0.813104,3.034545,0], v=0.02, r=0.005)  # [Rotate 30 deg around [0, 0, 1]]",
        "  movep(p[0.413346,0.29475,0.502999,-0.813104,3.034545,0], v=0.02, r=0.005)  # [Move [1, 2, 3] mm]",
        "  # [Set motion type to 'Joint']",
        "  # [Set motion speed to 45 mm/s or deg/s]",
        "  # WARNING: the same warning for 2 motions in a row, lines LINES (written once, above the first)",
        "  movej(p[-0.0015,0.250125,0.6,-0.813104,3.034545,0], v=0.785398, r=0.005)  # [Move to [-1.5, 250.125, 600] mm]",
        "  # [Set motion type to 'Linear']",
        "  # [Set precision radius to 0 mm]",
        "  movep(p[1000,0,0.6,-0.813104,3.034545,0], v=0.045, r=0)  # [Move to [1000000, 0, 600] mm]",
    ];

    [Fact]
    public void Emit_JointMotionMode_WritesMovejWithPoseAndAngularParameters()
    {
        var body = Body(Compile(bot => { bot.MotionMode("joint"); bot.SpeedTo(90); bot.AccelerationTo(180); Start(bot); }));
        Assert.Equal(["  movej(p[0.4,0.3,0.5,0,3.141593,0], a=3.141593, v=1.570796, r=0.005)"], body);
    }

    [Fact]
    public void Emit_ZeroAcceleration_LeavesOutA()
    {
        var body = Body(Compile(bot => { bot.AccelerationTo(0); bot.PrecisionTo(0); Start(bot); bot.AxesTo(0, 0, 0, 0, 90, 0); }));
        Assert.Equal(["  movep(p[0.4,0.3,0.5,0,3.141593,0], v=0.02, r=0)", "  movej([0,0,0,0,1.570796,0], v=0.349066, r=0)"], body);
    }

    [Fact]
    public void Emit_BuiltInAcceleration_LeftToTheControllerOtherValuesWritten()
    {
        // 30 mm/s² is Machina's default; written as a=0.03 it made the original's programs crawl (spec bug 34).
        var body = Body(Compile(bot => { bot.AccelerationTo(500); Start(bot); bot.AccelerationTo(30); bot.Move(0, 0, 10); }));
        Assert.Equal(["  movep(p[0.4,0.3,0.5,0,3.141593,0], a=0.5, v=0.02, r=0.005)", "  movep(p[0.4,0.3,0.51,0,3.141593,0], v=0.02, r=0.005)"], body);
    }

    [Fact]
    public void Emit_ArcMotion_WritesMovecThroughAndEnd()
    {
        var body = Body(Compile(bot => { Start(bot); bot.ArcMotion(50, 50, 0, 100, 0, 0); }));
        Assert.Equal("  movec(p[0.45,0.35,0.5,0,3.141593,0], p[0.5,0.3,0.5,0,3.141593,0], v=0.02, r=0.005)", body[1]);
    }

    [Fact]
    public void Emit_ArcWithThroughOrientationOffTheEvenTurn_Warns()
    {
        var down = Rotation.FlippedAroundY;
        var tilted = Rotation.FromAxisAngle(0, 1, 0, 30) * down;
        RobotProgram even = Compile(bot =>
        {
            Start(bot);
            bot.ArcMotionTo(new Plane(new Vector(450, 350, 500), Rotation.FromAxisAngle(0, 1, 0, 15) * down), new Plane(new Vector(500, 300, 500), tilted));
        });
        RobotProgram odd = Compile(bot =>
        {
            Start(bot);
            bot.ArcMotionTo(new Plane(new Vector(450, 350, 500), Rotation.FromAxisAngle(1, 0, 0, 40) * down), new Plane(new Vector(500, 300, 500), tilted));
        });
        Assert.Empty(even.Warnings);
        Assert.Contains("through point", Assert.Single(odd.Warnings).Message);
        Assert.StartsWith("  movec(p[0.45,0.35,0.5,", Body(odd)[1]);
    }

    [Fact]
    public void Emit_DeclaredTargets_AreNumberedWithoutGaps()
    {
        RobotProgram p = Compile(bot => { bot.Message("go"); Start(bot); bot.Wait(10); bot.ArcMotion(50, 50, 0, 100, 0, 0); bot.AxesTo(0, 0, 0, 0, 90, 0); },
            new CompileOptions { HumanComments = false, InlineTargets = false });
        Assert.Equal(
            ["  target0=p[0.4,0.3,0.5,0,3.141593,0]",
             "  target1=p[0.45,0.35,0.5,0,3.141593,0]",
             "  target2=p[0.5,0.3,0.5,0,3.141593,0]",
             "  target3=[0,0,0,0,1.570796,0]",
             "",
             "  popup(\"go\", title=\"Machina Message\", warning=False, error=False)",
             "  movep(target0, v=0.02, r=0.005)",
             "  sleep(0.01)",
             "  movec(target1, target2, v=0.02, r=0.005)",
             "  movej(target3, v=0.349066, r=0.005)"],
            Body(p));
    }

    [Fact]
    public void Emit_ToolAttachAndDetach_SetTcpAndPayload()
    {
        var body = Body(Compile(bot =>
        {
            bot.DefineTool("gripper", 10, 0, 150, 0, 1, 0, -1, 0, 0, 2.5, 0, 10, 60);
            bot.AttachTool("gripper");
            bot.DetachTool();
        }));
        Assert.Equal(
            ["  # Tool \"gripper\" defined",
             "  set_tcp(p[0.01,0,0.15,0,0,1.570796])",
             "  set_payload(2.5, [0,0.01,0.06])",
             "  set_tcp(p[0,0,0,0,0,0])",
             "  set_payload(0, [0,0,0])"],
            body);
    }

    [Fact]
    public void Emit_DigitalOutputs_UseStandardAndToolFunctions()
    {
        RobotProgram p = Compile(bot => { bot.WriteDigital(7, true); bot.WriteDigital(1, false, true); });
        Assert.Equal(["  set_standard_digital_out(7, True)", "  set_tool_digital_out(1, False)"], Body(p));
        Assert.Empty(p.Warnings);
    }

    [Fact]
    public void Emit_AnalogOutput_UsesStandardFunction()
    {
        Assert.Equal(["  set_standard_analog_out(1, 0.25)"], Body(Compile(bot => bot.WriteAnalog(1, 0.25))));
    }

    [Fact]
    public void Emit_OutputsTheRobotDoesNotHave_BecomeCommentsWithWarnings()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.WriteDigital(8, true);
            bot.WriteDigital(2, true, true);
            bot.WriteDigital("DO_1", true);
            bot.WriteAnalog(2, 0.5);
            bot.WriteAnalog(0, 1.5);
            bot.WriteAnalog(0, 0.5, true);
        });
        Assert.Equal(
            ["  # NOT SUPPORTED ON UR: Turn digital IO 8 ON",
             "  # NOT SUPPORTED ON UR: Turn tool digital IO 2 ON",
             "  # NOT SUPPORTED ON UR: Turn digital IO \"DO_1\" ON",
             "  # NOT SUPPORTED ON UR: Set analog IO 2 to 0.5",
             "  # NOT SUPPORTED ON UR: Set analog IO 0 to 1.5",
             "  # NOT SUPPORTED ON UR: Set tool analog IO 0 to 0.5"],
            Body(p));
        Assert.Equal(6, p.Warnings.Count);
        Assert.Equal("#1 WriteDigital(8,True); UR robots have standard digital outputs 0 to 7; output 8 does not exist.", p.Warnings[0].ToString());
        Assert.Contains("no analog outputs", p.Warnings[5].Message);
    }

    [Fact]
    public void Emit_MessageWithQuotesBackslashAndNewline_CannotBreakTheString()
    {
        RobotProgram p = Compile(bot => bot.Message("Say \"hi\")\nC:\\x"));
        Assert.Equal(["  popup(\"Say 'hi') C:/x\", title=\"Machina Message\", warning=False, error=False)"], Body(p));
        Assert.Single(p.Warnings);
    }

    [Fact]
    public void Emit_CommentWithLineBreak_StaysOnOneCommentLine()
    {
        Assert.Equal(["  # a movej([0,0,0,0,0,0]) b"], Body(Compile(bot => bot.Comment("a\nmovej([0,0,0,0,0,0])\rb"))));
    }

    [Fact]
    public void Emit_WaitAndCustomCode_WriteSleepAndStatement()
    {
        RobotProgram p = Compile(bot => { bot.CustomCode("global n = 0", true); bot.Wait(2500); bot.CustomCode("n = n + 1"); });
        var lines = p.GetFile("script")!.Lines.ToList();
        Assert.Equal("  global n = 0", lines[lines.IndexOf("def Demo():") + 2]);
        Assert.Equal(["  global n = 0", "", "  sleep(2.5)", "  n = n + 1"], Body(p));
    }

    [Fact]
    public void Emit_ExternalAxesArmAngleAndPrinterActions_BecomeCommentsWithWarnings()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.ExternalAxisTo(1, 100);
            bot.ArmAngleTo(20);
            bot.TemperatureTo(200, "extruder", false);
            bot.Extrude(true);
        });
        Assert.Equal(
            ["  # NOT SUPPORTED ON UR: Set external axis #1 to 100",
             "  # NOT SUPPORTED ON UR: Set arm-angle to 20 deg",
             "  # NOT SUPPORTED ON UR: Set Extruder temperature to 200 C",
             "  # NOT SUPPORTED ON UR: Turn extrusion on"],
            Body(p));
        Assert.Equal(4, p.Warnings.Count);
    }

    [Fact]
    public void Emit_HumanComments_AreAppendedAndSettingsGetCommentLines()
    {
        var body = Body(Compile(bot => { bot.SpeedTo(100); bot.Wait(5); }, CompileOptions.Default));
        Assert.Equal(["  # [Set motion speed to 100 mm/s or deg/s]", "  sleep(0.005)  # [Wait 5 ms]"], body);
    }

    [Theory]
    [InlineData("sleep", "def sleep_program():")]
    [InlineData("target3", "def target3_program():")]
    [InlineData("my bot", "def my_bot():")]
    public void Emit_ProgramName_IsAValidFunctionName(string robotName, string expected)
    {
        Assert.Contains(expected, Compile(Start, name: robotName).GetFile("script")!.Lines);
    }

    [Fact]
    public void Emit_ProgramStartingWithAttachedTool_SetsTcpAndPayloadFirst()
    {
        var bot = Robot.Create("Demo", RobotType.UR);
        bot.DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1, 0, 0, 50);
        bot.AttachTool("pen");
        bot.ClearProgram();
        bot.MoveTo(100, 100, 100);
        Assert.Equal(
            ["  set_tcp(p[0,0,0.1,0,0,0])", "  set_payload(1, [0,0,0.05])", "  movep(p[0.1,0.1,0.1,0,3.141593,0], v=0.02, r=0.005)"],
            Body(bot.Compile(RobotType.UR, TestCompile.Plain)));
    }

    [Fact]
    public void Emit_EmptyProgram_IsAnEmptyFunction()
    {
        var lines = Compile(_ => { }).GetFile("script")!.Lines.ToList();
        Assert.Equal(["def Demo():", "", "", "end", "", "Demo()"], lines.Skip(lines.IndexOf("def Demo():")));
    }

    [Fact]
    public void Compile_Twice_GivesIdenticalOutput()
    {
        var bot = Support.ReferencePrograms.Issue("JointsToolsIO", RobotType.UR);
        RobotProgram a = bot.Compile(RobotType.UR), b = bot.Compile(RobotType.UR);
        Assert.Equal(a.Files[0].ToText(), b.Files[0].ToText());
        Assert.Equal(a.Warnings, b.Warnings);
    }

    [Fact]
    public void Compile_UnderGermanCulture_UsesInvariantNumbers()
    {
        CultureInfo before = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            var body = Body(Compile(bot => { bot.SpeedTo(12.5); bot.MoveTo(0.5, 1.25, 2); bot.WriteAnalog(0, 0.75); bot.Wait(250); }));
            Assert.Equal(["  movep(p[0.0005,0.00125,0.002,0,3.141593,0], v=0.0125, r=0.005)", "  set_standard_analog_out(0, 0.75)", "  sleep(0.25)"], body);
        }
        finally
        {
            CultureInfo.CurrentCulture = before;
        }
    }
}
