using System.Globalization;
using Machina.Tests.Support;

namespace Machina.Tests.Brands.Kuka;

public class KrlCompilerTests
{
    private static Robot NewBot(string name = "Test") => Robot.Create(name, RobotType.KUKA);

    private static IReadOnlyList<string> Src(Robot bot, bool human = false, bool inline = true) =>
        bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = human, InlineTargets = inline }).Files[0].Lines;

    /// <summary>The lines after the fixed start block (which ends with the first empty line after "$APO.CDIS"), without the closing "", "END".</summary>
    private static string[] Body(Robot bot, bool human = false)
    {
        var lines = Src(bot, human).ToList();
        int start = lines.FindIndex(l => l.StartsWith("  $APO.CDIS", StringComparison.Ordinal)) + 2;
        return lines.Skip(start).Take(lines.Count - start - 2).ToArray();
    }

    [Fact]
    public void Compile_SettingsAndWait_NativeLines()
    {
        var bot = NewBot();
        bot.SpeedTo(250);
        bot.AccelerationTo(2500);
        bot.PrecisionTo(2.5);
        bot.Wait(1500);

        Assert.Equal(["  $VEL.CP = 0.25", "  $ACC.CP = 2.5", "  $APO.CDIS = 2.5", "  WAIT SEC 1.5"], Body(bot));
    }

    [Fact]
    public void Compile_StartBlock_UsesMachinaDefaultsAndBcoRun()
    {
        var lines = Src(NewBot());

        Assert.Equal("DEF Test( )", lines[4]);
        int bco = lines.ToList().IndexOf("  PTP $AXIS_ACT");
        Assert.True(bco > 0);
        // The built-in acceleration (30 mm/s²) is left to the controller (BAS sets it), not written as a crawling 0.03 m/s².
        Assert.Equal(["  $BASE = $NULLFRAME", "  $TOOL = $NULLFRAME", "  $ADVANCE = 3", "  $VEL.CP = 0.02", "  $APO.CDIS = 5", ""],
            lines.Skip(bco + 1).Take(6));
        Assert.Equal("END", lines[^1]);
    }

    [Fact]
    public void Compile_AccelerationZero_RestoresTheControllerDefault()
    {
        var bot = NewBot();
        bot.AccelerationTo(0);
        var lines = Src(bot);

        Assert.Contains("  DECL REAL machina_acc_cp", lines);
        Assert.Contains("  machina_acc_cp = $ACC.CP", lines);
        Assert.Equal(["  $ACC.CP = machina_acc_cp"], Body(bot));
    }

    [Fact]
    public void Compile_LinearAndJointMotions_ApproximationOnlyWhenPrecisionAboveZero()
    {
        var bot = NewBot();
        bot.MoveTo(100, 200, 300);
        bot.PrecisionTo(0);
        bot.Move(10, 0, 0);
        bot.MotionMode("joint");
        bot.Move(10, 0, 0);
        bot.PrecisionTo(1);
        bot.Move(10, 0, 0);
        bot.AxesTo(1, 2, 3, 4, 5, 6);

        string[] body = Body(bot);

        Assert.Equal(
            [
                "  LIN {E6POS: X 100, Y 200, Z 300, A 180, B 0, C 180} C_DIS",
                "  $APO.CDIS = 0",
                "  LIN {E6POS: X 110, Y 200, Z 300, A 180, B 0, C 180}",
                "  PTP {E6POS: X 120, Y 200, Z 300, A 180, B 0, C 180}",
                "  $APO.CDIS = 1",
                "  PTP {E6POS: X 130, Y 200, Z 300, A 180, B 0, C 180} C_PTP",
                "  PTP {AXIS: A1 1, A2 2, A3 3, A4 4, A5 5, A6 6} C_PTP",
            ],
            body.Where(l => !l.StartsWith("  ; WARNING", StringComparison.Ordinal)));
        Assert.Single(body, l => l.StartsWith("  ; WARNING: joint (PTP) motions", StringComparison.Ordinal));
    }

    [Fact]
    public void Compile_RepeatedMoves_OrientationDoesNotDrift()
    {
        // The original turned the cursor by +90 deg about Y every time it wrote a target (spec 13.6); here nothing accumulates.
        var bot = NewBot();
        bot.MoveTo(400, 0, 400);
        for (int i = 0; i < 5; i++)
        {
            bot.Move(0, 10, 0);
        }
        bot.Rotate(0, 0, 1, 90);
        bot.Move(0, 0, 10);

        string[] body = Body(bot);

        Assert.All(body.Take(6), l => Assert.EndsWith(", A 180, B 0, C 180} C_DIS", l));
        Assert.Equal("  LIN {E6POS: X 400, Y 50, Z 400, A -90, B 0, C 180} C_DIS", body[6]);
        Assert.Equal("  LIN {E6POS: X 400, Y 50, Z 410, A -90, B 0, C 180} C_DIS", body[7]);
    }

    [Fact]
    public void Compile_ArcMotion_WritesCircWithAuxiliaryAndEndPoints()
    {
        var bot = NewBot();
        bot.MoveTo(0, 0, 100);
        bot.ArcMotionTo(10, 10, 100, 20, 0, 100);

        Assert.Equal(
            "  CIRC {E6POS: X 10, Y 10, Z 100, A 180, B 0, C 180}, {E6POS: X 20, Y 0, Z 100, A 180, B 0, C 180} C_DIS",
            Body(bot)[1]);
    }

    [Fact]
    public void Compile_ExternalAxes_GoIntoE6PosAndE6Axis()
    {
        var bot = NewBot();
        bot.ExternalAxisTo(1, 500);
        bot.ExternalAxisTo(2, -45.5, ExternalAxesTarget.Joint);
        bot.MoveTo(100, 0, 300);
        bot.AxesTo(0, 0, 90, 0, 0, 0);

        string[] body = Body(bot).Where(l => !l.StartsWith("  ; WARNING", StringComparison.Ordinal)).ToArray();

        Assert.Equal(
            [
                "  LIN {E6POS: X 100, Y 0, Z 300, A 180, B 0, C 180, E1 500} C_DIS",
                "  PTP {E6AXIS: A1 0, A2 0, A3 90, A4 0, A5 0, A6 0, E1 500, E2 -45.5} C_PTP",
            ],
            body);
    }

    [Fact]
    public void Compile_ToolAttachAndDetach_ToolFrameAndLoadWarning()
    {
        var bot = NewBot();
        bot.MoveTo(400, 0, 400);
        bot.DefineTool("gripper", 10, 0, 150, 0, 1, 0, -1, 0, 0, 2, 0, 0, 75);
        bot.AttachTool("gripper");
        bot.DetachTool();

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });
        string[] body = Body(bot);

        Assert.Equal(
            [
                "  LIN {E6POS: X 400, Y 0, Z 400, A 180, B 0, C 180} C_DIS",
                "  ; WARNING: set the load data (weight 2 kg) of tool \"gripper\" on the controller.",
                "  $TOOL = {X 10, Y 0, Z 150, A 90, B 0, C 0}",
                "  $TOOL = $NULLFRAME",
            ],
            body);
        Assert.Single(program.Warnings);
        Assert.Equal(3, program.Warnings[0].ActionId);
    }

    [Fact]
    public void Compile_ToolAttachedBeforeTheProgram_StartsWithThatTool()
    {
        var bot = NewBot();
        bot.DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50);
        bot.AttachTool("pen");
        bot.ClearProgram();
        bot.SpeedTo(10);

        Assert.Contains("  $TOOL = {X 0, Y 0, Z 100, A 0, B 0, C 0}", Src(bot));
    }

    [Fact]
    public void Compile_DigitalAndAnalogOutputs_NativeLinesOrErrors()
    {
        var bot = NewBot();
        bot.WriteDigital(5, true);
        bot.WriteDigital(5000, true);
        bot.WriteDigital(3, false, toolPin: true);
        bot.WriteDigital("DO_Clamp", false);
        bot.WriteDigital("9lives", false);
        bot.WriteAnalog(2, -0.25);
        bot.WriteAnalog(2, 1.5);
        bot.WriteAnalog(33, 0.5);

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });
        string[] body = Body(bot);

        Assert.Equal("  $OUT[5] = TRUE", body[0]);
        Assert.Equal("  ; ERROR on \"Turn digital IO 5000 ON\": $OUT outputs are numbered 1 to 4096, so output 5000 does not exist.", body[1]);
        Assert.StartsWith("  ; ERROR on \"Turn tool digital IO 3 OFF\": KUKA controllers have no separate tool outputs", body[2], StringComparison.Ordinal);
        Assert.Equal("  DO_Clamp = FALSE", body[3]);
        Assert.StartsWith("  ; ERROR on \"Turn digital IO \"9lives\" OFF\"", body[4], StringComparison.Ordinal);
        Assert.Equal("  $ANOUT[2] = -0.25", body[5]);
        Assert.Equal("  ; ERROR on \"Set analog IO 2 to 1.5\": KRL analog outputs take values from -1 to 1, and 1.5 is outside that range.", body[6]);
        Assert.StartsWith("  ; ERROR on \"Set analog IO 33 to 0.5\": $ANOUT outputs are numbered 1 to 32", body[7], StringComparison.Ordinal);
        Assert.Equal([2, 3, 5, 7, 8], program.Warnings.Select(w => w.ActionId));
    }

    [Fact]
    public void Compile_PopSettings_ReemitsEveryRestoredSetting()
    {
        var bot = NewBot();
        bot.PushSettings();
        bot.SpeedTo(300);
        bot.AccelerationTo(800);
        bot.PrecisionTo(0);
        bot.PopSettings();
        bot.PushSettings();
        bot.PopSettings();

        Assert.Equal(
            ["  $VEL.CP = 0.3", "  $ACC.CP = 0.8", "  $APO.CDIS = 0", "  $VEL.CP = 0.02", "  $ACC.CP = machina_acc_cp", "  $APO.CDIS = 5"],
            Body(bot));
    }

    [Fact]
    public void Compile_PrinterActionsOnAnArm_CommentAndWarningEach()
    {
        var bot = NewBot();
        bot.TemperatureTo(200, "extruder");
        bot.ExtrusionRateTo(0.1);
        bot.Extrude();
        bot.Initialize();
        bot.ArmAngleTo(30);

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });
        string[] body = Body(bot);

        Assert.Equal(5, body.Length);
        Assert.All(body, l => Assert.Matches("^  ; ACTION \".*\" NOT APPLICABLE TO THIS DEVICE$", l));
        Assert.Equal([1, 2, 3, 4, 5], program.Warnings.Select(w => w.ActionId));
        Assert.Contains("3D printers", program.Warnings[0].Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Compile_UserText_CannotBreakOutOfComments()
    {
        var bot = NewBot();
        bot.Message("Hi\nLIN {X 0}\r\nEND");
        bot.Comment("note\nPTP $AXIS_ACT");

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = true });
        string[] body = Body(bot, human: true);

        Assert.Equal(
            [
                "  ; MESSAGE: Hi LIN {X 0}  END  ; [Display message \"Hi LIN {X 0}  END\"]",
                "  ; note PTP $AXIS_ACT",
            ],
            body);
        Assert.Single(program.Warnings);
        Assert.All(program.Files[0].Lines, l => Assert.DoesNotContain('\n', l));
    }

    [Fact]
    public void Compile_CustomCode_DeclarationsGoBeforeTheIniFold()
    {
        var bot = NewBot();
        bot.CustomCode("DECL INT counter", isDeclaration: true);
        bot.CustomCode("counter = counter + 1");

        var lines = Src(bot).ToList();

        Assert.True(lines.IndexOf("  DECL INT counter") < lines.IndexOf(";FOLD INI"));
        Assert.Equal(["  counter = counter + 1"], Body(bot));
    }

    [Fact]
    public void Compile_DeclaredTargets_LiveInTheDatFileInOrder()
    {
        var bot = NewBot();
        bot.MoveTo(0, 0, 100);
        bot.ArcMotionTo(10, 10, 100, 20, 0, 100);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false, InlineTargets = false });

        Assert.Equal(["Test.src", "Test.dat"], program.Files.Select(f => f.FileName));
        Assert.Contains("  CIRC target2, target3 C_DIS", program.Files[0].Lines);
        Assert.Contains("  PTP target4 C_PTP", program.Files[0].Lines);
        Assert.Equal("DECL AXIS target4={A1 0, A2 0, A3 0, A4 0, A5 90, A6 0}", program.Files[1].Lines[^3]);
        Assert.Equal("ENDDAT", program.Files[1].Lines[^1]);
    }

    [Fact]
    public void Compile_KeywordOrLongRobotName_ModuleAndFileNamesAgree()
    {
        RobotProgram program = NewBot("Circ").Compile(RobotType.KUKA);

        Assert.Equal("M_Circ.src", program.Files[0].FileName);
        Assert.Contains("DEF M_Circ( )", program.Files[0].Lines);
    }

    [Fact]
    public void Compile_Twice_GivesIdenticalPrograms()
    {
        Robot bot = ReferencePrograms.Issue("Rotations", RobotType.KUKA);

        Assert.Equal(Src(bot, human: true), Src(bot, human: true));
        Assert.Equal(Src(bot, inline: false), Src(bot, inline: false));
    }

    [Fact]
    public void Compile_UnderGermanCulture_SameText()
    {
        Robot bot = ReferencePrograms.Issue("JointsToolsIO", RobotType.KUKA);
        var expected = Src(bot, human: true);
        CultureInfo saved = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            Assert.Equal(expected, Src(bot, human: true));
        }
        finally
        {
            CultureInfo.CurrentCulture = saved;
        }
        Assert.Contains("  $ANOUT[2] = 0.5  ; [Set analog IO 2 to 0.5]", expected);
    }

    [Theory]
    [MemberData(nameof(KrlGoldenTests.ReferenceProgramNames), MemberType = typeof(KrlGoldenTests))]
    public void Compile_ReferencePrograms_NoTrailingSpacesAndAsciiOnly(string name)
    {
        Robot bot = ReferencePrograms.Issue(name, RobotType.KUKA);
        foreach (bool inline in new[] { true, false })
        {
            foreach (RobotProgramFile file in bot.Compile(RobotType.KUKA, new CompileOptions { InlineTargets = inline }).Files)
            {
                Assert.All(file.Lines, l => Assert.False(l.EndsWith(' '), $"trailing space in \"{l}\""));
                Assert.All(file.Lines, l => Assert.True(l.All(char.IsAscii), l));
            }
        }
    }

    [Fact]
    public void CompileToFolder_DeclaredTargets_WritesTheSameSrcAndDatAsInMemory()
    {
        Robot bot = ReferencePrograms.Issue("HelloRobot", RobotType.KUKA);
        var options = new CompileOptions { InlineTargets = false };
        string folder = Path.Combine(Path.GetTempPath(), "machina-krl-" + Guid.NewGuid().ToString("N"));
        try
        {
            IReadOnlyList<string> paths = bot.CompileToFolder(folder, RobotType.KUKA, options);
            RobotProgram program = bot.Compile(RobotType.KUKA, options);

            Assert.Equal(["HelloRobot.src", "HelloRobot.dat"], paths.Select(Path.GetFileName));
            Assert.Equal(program.Files[0].ToText(), File.ReadAllText(paths[0]));
            Assert.Equal(program.Files[1].ToText(), File.ReadAllText(paths[1]));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void Compile_HelloRobot_WarnsAboutTheMessageAndThePtpSpeed()
    {
        RobotProgram program = ReferencePrograms.Issue("HelloRobot", RobotType.KUKA).Compile();

        Assert.Equal([1, 7], program.Warnings.Select(w => w.ActionId));
        Assert.Equal("Message(\"Hello Robot!\");", program.Warnings[0].Instruction);
        Assert.StartsWith("joint (PTP) motions", program.Warnings[1].Message, StringComparison.Ordinal);
    }
}
