using System.Globalization;
using Machina.Tests.Support;

namespace Machina.Tests.Brands.Abb;

public class RapidCompilerTests
{
    private static RobotProgram Compile(Action<Robot> issue, CompileOptions? options = null, string name = "Demo") =>
        TestCompile.Program(RobotType.ABB, issue, options, name);

    /// <summary>The instruction lines of PROC main, without the fixed start lines and the blank lines around them.</summary>
    internal static List<string> MainLines(RobotProgram program)
    {
        var lines = program.GetFile("mod")!.Lines.ToList();
        int start = lines.IndexOf("  PROC main()") + 5;
        int end = lines.IndexOf("  ENDPROC") - 1;
        return lines.GetRange(start, end - start);
    }

    /// <summary>The declaration lines of the module (CONST and PERS).</summary>
    internal static List<string> Declarations(RobotProgram program) =>
        program.GetFile("mod")!.Lines.Where(l => l.StartsWith("  CONST ", StringComparison.Ordinal) || l.StartsWith("  PERS ", StringComparison.Ordinal)).ToList();

    private static void Start(Robot bot) => bot.MoveTo(400, 300, 500);

    [Fact]
    public void Emit_InlineMoveComments_AreThoseOfTheDeclaredTargetsLines()
    {
        // The inline line writes a move's description in its place (translations, rotations) or from its text (a transformation);
        // the lines with declared targets append it through a builder: both must carry the same comment.
        void Issue(Robot bot)
        {
            Start(bot);
            bot.Move(12.5, -3, 0.25);
            bot.Rotate(0, 0, 1, 33.3);
            bot.TransformTo(new Vector(123456.789, -98765.4321, 555.5), Rotation.FromAxisAngle(1, 1, 0, 47.25));
        }
        static string Comment(string line) => line[line.IndexOf("  ! [", StringComparison.Ordinal)..];
        List<string> inline = MainLines(Compile(Issue, new CompileOptions { HumanComments = true }))
            .Where(l => l.StartsWith("    Move", StringComparison.Ordinal)).ToList();
        List<string> declared = MainLines(Compile(Issue, new CompileOptions { HumanComments = true, InlineTargets = false }))
            .Where(l => l.StartsWith("    Move", StringComparison.Ordinal)).ToList();
        Assert.Equal(4, inline.Count);
        Assert.Equal(declared.Select(Comment), inline.Select(Comment));
        Assert.EndsWith("]", inline[3]);
        Assert.Contains("123456.789", Comment(inline[3]));
    }

    [Fact]
    public void Emit_ProgramStart_ResetsConfigurationAndAcceleration()
    {
        var lines = Compile(Start).GetFile("mod")!.Lines.ToList();
        int main = lines.IndexOf("  PROC main()");
        Assert.Equal(["    ConfJ \\Off;", "    ConfL \\Off;", "    WorldAccLim \\Off;", ""], lines.GetRange(main + 1, 4));
        Assert.Equal(["MODULE Demo", ""], lines.GetRange(0, 2));
        Assert.Equal(["  ENDPROC", "", "ENDMODULE"], lines.TakeLast(3));
    }

    [Fact]
    public void Emit_Pgf_NamesTheModuleFile()
    {
        Assert.Equal(
            ["<?xml version=\"1.0\" encoding=\"ISO-8859-1\" ?>", "<Program>", "    <Module>Demo.mod</Module>", "</Program>"],
            Compile(Start).GetFile("pgf")!.Lines);
    }

    [Fact]
    public void Emit_SpeedsThatRoundAlike_ShareOneDeclaration()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.SpeedTo(100);
            Start(bot);
            bot.SpeedTo(100.0001);
            bot.Move(10, 0, 0);
            bot.SpeedTo(2.5);
            bot.Move(10, 0, 0);
        });
        Assert.Equal(["  CONST speeddata vel100 := [100,100,100,100];", "  CONST speeddata vel2_5 := [2.5,2.5,2.5,2.5];"], Declarations(p));
        Assert.EndsWith(", vel100, z5, Tool0\\WObj:=WObj0;", MainLines(p)[1]);
        Assert.EndsWith(", vel2_5, z5, Tool0\\WObj:=WObj0;", MainLines(p)[2]);
    }

    [Fact]
    public void Emit_SpeedsAndZonesComingBack_EachDeclaredOnceInOrderOfFirstUse()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.SpeedTo(50);
            Start(bot);
            bot.SpeedTo(60);
            bot.PrecisionTo(7.5);
            bot.Move(10, 0, 0);
            bot.SpeedTo(50);
            bot.PrecisionTo(5);
            bot.Move(10, 0, 0);
            bot.SpeedTo(70);
            bot.PrecisionTo(7.5);
            bot.Move(10, 0, 0);
            bot.SpeedTo(60);
            bot.Move(10, 0, 0);
        });
        Assert.Equal(
            ["  CONST speeddata vel50 := [50,50,50,50];", "  CONST speeddata vel60 := [60,60,60,60];", "  CONST speeddata vel70 := [70,70,70,70];",
             "  CONST zonedata zone7_5 := [FALSE,7.5,11.25,11.25,0.75,11.25,0.75];"],
            Declarations(p));
        Assert.EndsWith(", vel50, z5, Tool0\\WObj:=WObj0;", MainLines(p)[2]);
        Assert.EndsWith(", vel60, zone7_5, Tool0\\WObj:=WObj0;", MainLines(p)[4]);
    }

    [Fact]
    public void Emit_SpeedNeverUsedByAMotion_IsNotDeclared()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.SpeedTo(77);
            bot.SpeedTo(50);
            Start(bot);
        });
        Assert.Equal(["  CONST speeddata vel50 := [50,50,50,50];"], Declarations(p));
    }

    [Fact]
    public void Emit_Precisions_UseFinePredefinedOrDeclaredZones()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.PrecisionTo(0);
            Start(bot);
            bot.PrecisionTo(10);
            bot.Move(1, 0, 0);
            bot.PrecisionTo(2.5);
            bot.Move(1, 0, 0);
        });
        Assert.EndsWith(", vel20, fine, Tool0\\WObj:=WObj0;", MainLines(p)[0]);
        Assert.EndsWith(", vel20, z10, Tool0\\WObj:=WObj0;", MainLines(p)[1]);
        Assert.EndsWith(", vel20, zone2_5, Tool0\\WObj:=WObj0;", MainLines(p)[2]);
        Assert.Contains("  CONST zonedata zone2_5 := [FALSE,2.5,3.75,3.75,0.25,3.75,0.25];", Declarations(p));
        Assert.DoesNotContain(Declarations(p), l => l.Contains("zonedata z10", StringComparison.Ordinal) || l.Contains("fine", StringComparison.Ordinal));
    }

    [Fact]
    public void Emit_Translation_WritesInlineRobTarget()
    {
        Assert.Equal(
            ["    MoveL [[400, 300, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;"],
            MainLines(Compile(Start)));
    }

    [Fact]
    public void Emit_JointMotionMode_WritesMoveJ()
    {
        var main = MainLines(Compile(bot => { bot.MotionMode("joint"); Start(bot); }));
        Assert.StartsWith("    MoveJ [[400, 300, 500], ", main[0]);
    }

    [Fact]
    public void Emit_ArcMotion_WritesMoveCThroughAndEnd()
    {
        var main = MainLines(Compile(bot => { Start(bot); bot.ArcMotion(50, 50, 0, 100, 0, 0); }));
        Assert.Equal(
            "    MoveC [[450, 350, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], " +
            "[[500, 300, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;", main[1]);
    }

    [Fact]
    public void Emit_ArcMotionWithDeclaredTargets_DeclaresThroughAndEnd()
    {
        RobotProgram p = Compile(bot => { Start(bot); bot.ArcMotion(50, 50, 0, 100, 0, 0); }, new CompileOptions { HumanComments = false, InlineTargets = false });
        Assert.Equal("    MoveC target1, target2, vel20, z5, Tool0\\WObj:=WObj0;", MainLines(p)[1]);
        Assert.Equal("  CONST robtarget target1 := [[450, 350, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]];", Declarations(p)[2]);
    }

    [Fact]
    public void Emit_ExternalAxesAndArmAngle_FillRobTargetAndJointTarget()
    {
        var main = MainLines(Compile(bot =>
        {
            bot.ExternalAxisTo(2, 100.5);
            bot.ArmAngleTo(-30);
            Start(bot);
            bot.ExternalAxisTo(1, 45, ExternalAxesTarget.Joint);
            bot.AxesTo(0, 0, 0, 0, 90, 0);
        }));
        Assert.Equal("    MoveL [[400, 300, 500], [0, 0, 1, 0], [0,0,0,0], [-30,100.5,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;", main[0]);
        Assert.Equal("    MoveAbsJ [[0, 0, 0, 0, 90, 0], [45,100.5,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;", main[1]);
    }

    [Theory]
    [InlineData(500, "    WorldAccLim \\On := 0.5;")]
    [InlineData(2500, "    WorldAccLim \\On := 2.5;")]
    [InlineData(0, "    WorldAccLim \\Off;")]
    public void Emit_Acceleration_WritesWorldAccLimInMetresPerSecondSquared(double acceleration, string expected)
    {
        RobotProgram p = Compile(bot => bot.AccelerationTo(acceleration));
        Assert.Equal([expected], MainLines(p));
        Assert.Empty(p.Warnings);
    }

    [Fact]
    public void Emit_AccelerationBelowControllerMinimum_IsRaisedWithWarning()
    {
        RobotProgram p = Compile(bot => bot.AccelerationTo(50));
        Assert.Equal(["    WorldAccLim \\On := 0.1;"], MainLines(p));
        Assert.Contains("0.1 m/s^2", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void Emit_PopRestoringAcceleration_WritesWorldAccLim()
    {
        var main = MainLines(Compile(bot =>
        {
            bot.AccelerationTo(500);
            bot.PushSettings();
            bot.AccelerationTo(1000);
            bot.SpeedTo(100);
            bot.PopSettings();
            bot.PushSettings();
            bot.SpeedTo(10);
            bot.PopSettings();
        }));
        Assert.Equal(["    WorldAccLim \\On := 0.5;", "    WorldAccLim \\On := 1;", "    WorldAccLim \\On := 0.5;"], main);
    }

    [Fact]
    public void Emit_Wait_WritesSeconds()
    {
        Assert.Equal(["    WaitTime 1.5;", "    WaitTime 0.001;"], MainLines(Compile(bot => { bot.Wait(1500); bot.Wait(1); })));
    }

    [Fact]
    public void Emit_MessageWithQuotesBackslashAndNewline_IsEscapedAndSplitPerLine()
    {
        RobotProgram p = Compile(bot => bot.Message("Say \"hi\"\nC:\\temp"));
        Assert.Equal(["    TPWrite \"Say \"\"hi\"\"\";", "    TPWrite \"C:\\\\temp\";"], MainLines(p));
        Assert.Empty(p.Warnings);
    }

    [Fact]
    public void Emit_MessageLongerThan80Characters_IsSplitWithWarning()
    {
        string text = new string('a', 80) + "bcd";
        RobotProgram p = Compile(bot => bot.Message(text));
        Assert.Equal(["    TPWrite \"" + new string('a', 80) + "\";", "    TPWrite \"bcd\";"], MainLines(p));
        Assert.Contains("80 characters", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void Emit_MessageWithNonAscii_IsReplacedWithWarning()
    {
        RobotProgram p = Compile(bot => bot.Message("Grüße"));
        Assert.Equal(["    TPWrite \"Gr??e\";"], MainLines(p));
        Assert.Single(p.Warnings);
    }

    [Fact]
    public void Emit_CommentWithLineBreaks_StaysOnOneCommentLine()
    {
        RobotProgram p = Compile(bot => bot.Comment("first\nMoveL evil;\r\nthird"));
        Assert.Equal(["    ! first MoveL evil;  third"], MainLines(p));
    }

    [Fact]
    public void Emit_HumanCommentWithLineBreak_StaysOnOneLine()
    {
        RobotProgram p = Compile(bot => bot.Message("a\nb"), CompileOptions.Default);
        Assert.Equal(["    TPWrite \"a\";  ! [Display message \"a b\"]", "    TPWrite \"b\";"], MainLines(p));
    }

    [Fact]
    public void Emit_MillionCharacterMessageWithHumanComments_CommentsOnlyItsFirstLine()
    {
        // Each of the 12,500 TPWrite lines used to carry the whole message as its comment: 25 GB, and the process died.
        RobotProgram p = Compile(bot => bot.Message(new string('m', 1_000_000)), CompileOptions.Default);

        List<string> lines = MainLines(p);
        Assert.Equal(12_500, lines.Count);
        Assert.Equal("    TPWrite \"" + new string('m', 80) + "\";  ! [Display message \"" + new string('m', 1_000_000) + "\"]", lines[0]);
        Assert.All(lines.Skip(1), l => Assert.Equal("    TPWrite \"" + new string('m', 80) + "\";", l));
    }

    [Fact]
    public void Emit_AttachedTool_IsDeclaredWithMassAndCentreOfGravity()
    {
        RobotProgram p = Compile(bot =>
        {
            Start(bot);
            bot.DefineTool("gripper", 0, 0, 150, 1, 0, 0, 0, 1, 0, 2.5, 0, 10, 60);
            bot.DefineTool("unused", 0, 0, 10, 1, 0, 0, 0, 1, 0, 1, 0, 0, 5);
            bot.AttachTool("gripper");
            bot.Move(0, 0, 10);
        });
        Assert.Equal("  PERS tooldata gripper := [TRUE,[[0,0,150],[1,0,0,0]],[2.5,[0,10,60],[1,0,0,0],0,0,0]];", Declarations(p)[0]);
        Assert.DoesNotContain(Declarations(p), l => l.Contains("unused", StringComparison.Ordinal));
        Assert.Equal(
            ["    MoveL [[400, 300, 500], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;",
             "    ! Tool \"gripper\" defined", "    ! Tool \"unused\" defined", "    ! Tool \"gripper\" attached",
             "    MoveL [[400, 300, 360], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, gripper\\WObj:=WObj0;"],
            MainLines(p));
    }

    [Fact]
    public void Emit_ToolNamesClashingWithRapidNames_AreRenamedWithWarning()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.SpeedTo(100);
            Start(bot);
            bot.DefineTool("vel100", 0, 0, 10, 1, 0, 0, 0, 1, 0, 1, 0, 0, 5);
            bot.AttachTool("vel100");
            bot.Move(0, 0, 10);
            bot.DefineTool("tool0", 0, 0, 20, 1, 0, 0, 0, 1, 0, 0, 0, 0, 5);
            bot.AttachTool("tool0");
            bot.Move(0, 0, 10);
        });
        Assert.Contains("  PERS tooldata vel100_2 := [TRUE,[[0,0,10],[1,0,0,0]],[1,[0,0,5],[1,0,0,0],0,0,0]];", Declarations(p));
        Assert.Contains("  PERS tooldata tool0_2 := [TRUE,[[0,0,20],[1,0,0,0]],[0.001,[0,0,5],[1,0,0,0],0,0,0]];", Declarations(p));
        Assert.Contains("  CONST speeddata vel100 := [100,100,100,100];", Declarations(p));
        Assert.EndsWith("vel100, z5, vel100_2\\WObj:=WObj0;", MainLines(p)[3]);
        Assert.Equal(3, p.Warnings.Count);
    }

    [Fact]
    public void Emit_ToolAttachedButNeverMoved_IsNotDeclared()
    {
        RobotProgram p = Compile(bot => { bot.DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0, 0, 0, 5); bot.AttachTool("pen"); });
        Assert.Empty(Declarations(p));
        Assert.Equal(["    ! Tool \"pen\" defined", "    ! Tool \"pen\" attached"], MainLines(p));
        Assert.Empty(p.Warnings);
    }

    [Fact]
    public void Emit_NamedSignals_WriteSetDOAndSetAO()
    {
        RobotProgram p = Compile(bot => { bot.WriteDigital("DO_1", true); bot.WriteAnalog("AO_speed", 0.25); bot.WriteDigital("DO_2", false, true); });
        Assert.Equal(["    SetDO DO_1, 1;", "    SetAO AO_speed, 0.25;", "    SetDO DO_2, 0;"], MainLines(p));
        Assert.Contains("  ! This program sets IO signals: each signal name must exist in the controller's IO configuration.", p.GetFile("mod")!.Lines);
    }

    [Fact]
    public void Emit_NumberedOrInvalidSignal_BecomesCommentWithWarning()
    {
        RobotProgram p = Compile(bot => { bot.WriteDigital(3, true); bot.WriteAnalog("AO-1", 1); });
        Assert.Equal(["    ! NOT SUPPORTED ON ABB: Turn digital IO 3 ON", "    ! NOT SUPPORTED ON ABB: Set analog IO \"AO-1\" to 1"], MainLines(p));
        Assert.Equal(2, p.Warnings.Count);
        Assert.Equal("WriteDigital(3,True);", p.Warnings[0].Instruction);
    }

    [Fact]
    public void Emit_PrinterActions_BecomeCommentsWithWarnings()
    {
        RobotProgram p = Compile(bot =>
        {
            bot.Initialize();
            bot.TemperatureTo(200, "extruder", true);
            bot.ExtrusionRateTo(0.1);
            bot.Extrude(true);
            bot.Terminate();
        });
        Assert.Equal(
            ["    ! Initialize this device. (nothing to do on an ABB robot)",
             "    ! NOT SUPPORTED ON ABB: Set Extruder temperature to 200 C and wait",
             "    ! NOT SUPPORTED ON ABB: Set extrusion rate to 0.1 mm/mm",
             "    ! NOT SUPPORTED ON ABB: Turn extrusion on",
             "    ! Terminate this device. (nothing to do on an ABB robot)"],
            MainLines(p));
        Assert.Equal(3, p.Warnings.Count);
    }

    [Fact]
    public void Emit_CustomCode_GoesToDeclarationsOrInPlace()
    {
        RobotProgram p = Compile(bot => { bot.CustomCode("VAR num counter := 0;", true); bot.CustomCode("counter := counter + 1;"); });
        Assert.Contains("  VAR num counter := 0;", p.GetFile("mod")!.Lines);
        Assert.Equal(["    counter := counter + 1;"], MainLines(p));
    }

    [Fact]
    public void Emit_SettingsWithHumanComments_GiveCommentOnlyLines()
    {
        var main = MainLines(Compile(bot => { bot.SpeedTo(50); bot.PushSettings(); }, CompileOptions.Default));
        Assert.Equal(["    ! [Set motion speed to 50 mm/s or deg/s]", "    ! [Push settings to buffer]"], main);
        Assert.Empty(MainLines(Compile(bot => { bot.SpeedTo(50); bot.PushSettings(); })));
    }

    [Fact]
    public void Emit_ProgramNamedLikeReservedWord_GivesValidModuleName()
    {
        RobotProgram p = Compile(Start, name: "Main");
        Assert.Equal("MODULE Main_2", p.GetFile("mod")!.Lines[0]);
        Assert.Equal("Main.mod", p.GetFile("mod")!.FileName);
    }

    [Theory]
    [InlineData("target1", "MODULE M_target1")]
    [InlineData("Z5", "MODULE Z5_2")]
    [InlineData("vel20", "MODULE vel20")]
    public void Emit_ProgramNamedLikeGeneratedOrPredefinedData_GetsDistinctModuleName(string robotName, string expected)
    {
        RobotProgram p = Compile(Start, new CompileOptions { HumanComments = false, InlineTargets = false }, robotName);
        Assert.Equal(expected, p.GetFile("mod")!.Lines[0]);
        Assert.Contains(Declarations(p), l => l.StartsWith("  CONST speeddata vel20", StringComparison.Ordinal));
        Assert.Equal(2, Declarations(p).Count);
    }

    [Fact]
    public void Emit_VeryLongProgramName_IsCutTo32Characters()
    {
        RobotProgram p = Compile(Start, name: new string('r', 40));
        Assert.Equal("MODULE " + new string('r', 32), p.GetFile("mod")!.Lines[0]);
    }

    [Fact]
    public void Emit_ProgramStartingWithToolAndAcceleration_DeclaresToolAndSetsLimit()
    {
        var bot = Robot.Create("Demo", RobotType.ABB);
        bot.DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1, 0, 0, 50);
        bot.AttachTool("pen");
        bot.AccelerationTo(1200);
        bot.ClearProgram();
        bot.MoveTo(100, 100, 100);
        RobotProgram p = bot.Compile(RobotType.ABB, TestCompile.Plain);
        Assert.Equal("  PERS tooldata pen := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];", Declarations(p)[0]);
        Assert.Contains("    WorldAccLim \\On := 1.2;", p.GetFile("mod")!.Lines);
        Assert.EndsWith(", vel20, z5, pen\\WObj:=WObj0;", MainLines(p)[0]);
    }

    [Fact]
    public void Compile_Twice_GivesIdenticalOutput()
    {
        var bot = Support.ReferencePrograms.Issue("JointsToolsIO", RobotType.ABB);
        RobotProgram a = bot.Compile(RobotType.ABB), b = bot.Compile(RobotType.ABB);
        Assert.Equal(a.GetFile("mod")!.ToText(), b.GetFile("mod")!.ToText());
        Assert.Equal(a.Warnings, b.Warnings);
    }

    [Fact]
    public void Compile_UnderGermanCulture_UsesInvariantNumbers()
    {
        CultureInfo before = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            RobotProgram p = Compile(bot => { bot.SpeedTo(12.5); bot.AccelerationTo(1500); bot.MoveTo(0.5, 1.25, 2); bot.WriteAnalog("AO_1", 0.75); bot.Wait(250); });
            string text = p.GetFile("mod")!.ToText();
            Assert.Contains("[[0.5, 1.25, 2], [0, 0, 1, 0]", text, StringComparison.Ordinal);
            Assert.Contains("WorldAccLim \\On := 1.5;", text, StringComparison.Ordinal);
            Assert.Contains("SetAO AO_1, 0.75;", text, StringComparison.Ordinal);
            Assert.Contains("WaitTime 0.25;", text, StringComparison.Ordinal);
            Assert.Contains("CONST speeddata vel12_5 := [12.5,12.5,12.5,12.5];", text, StringComparison.Ordinal);
        }
        finally
        {
            CultureInfo.CurrentCulture = before;
        }
    }
}
