using Machina.Tests.Support;

namespace Machina.Tests.Programs;

/// <summary>Audit findings: user texts and extreme numbers that used to break or silently change compiled programs.</summary>
public class CompilerEdgeCaseTests
{
    private static RobotProgram Compile(RobotType brand, Action<Robot> issue, CompileOptions? options = null, string name = "Demo") =>
        TestCompile.Program(brand, issue, options, name);

    private static List<string> Lines(RobotProgram program, string extension) => program.GetFile(extension)!.Lines.ToList();

    [Fact]
    public void Human_MessageWithLineBreaks_StaysOnOneListingLine()
    {
        RobotProgram p = Compile(RobotType.HUMAN, b => { b.Message("one\ntwo\r\nthree"); b.Comment("a\rb\tc"); });

        List<string> lines = Lines(p, "txt");
        Assert.Equal(["[0] Display message \"one two  three\"", "[1] Comment: \"a b c\""], lines.TakeLast(2));
    }

    [Fact]
    public void Rapid_SpeedThatRoundsToZero_IsRaisedToTheSmallestSpeedWithAWarning()
    {
        RobotProgram p = Compile(RobotType.ABB, b => { b.SpeedTo(0.0001); b.MoveTo(300, 0, 300); });

        List<string> mod = Lines(p, "mod");
        Assert.Contains("  CONST speeddata vel0_001 := [0.001,0.001,0.001,0.001];", mod);
        Assert.Contains(mod, l => l.Contains("MoveL", StringComparison.Ordinal) && l.Contains(", vel0_001, ", StringComparison.Ordinal));
        Assert.Contains(p.Warnings, w => w.Instruction == "SpeedTo(0.0001);" && w.Message.Contains("0.001 mm/s", StringComparison.Ordinal));
    }

    [Fact]
    public void UrScript_SpeedAndAccelerationThatRoundToZero_AreRaisedWithWarnings()
    {
        RobotProgram p = Compile(RobotType.UR, b => { b.SpeedTo(0.0001); b.AccelerationTo(0.0001); b.MoveTo(300, 0, 300); });

        List<string> script = Lines(p, "script");
        Assert.Contains("  movep(p[0.3,0,0.3,0,3.141593,0], a=0.000001, v=0.000001, r=0.005)", script);
        Assert.Contains(p.Warnings, w => w.Instruction == "SpeedTo(0.0001);");
        Assert.Contains(p.Warnings, w => w.Instruction == "AccelerationTo(0.0001);");
    }

    [Fact]
    public void Krl_SpeedAndAccelerationThatRoundToZero_AreRaisedWithWarnings()
    {
        RobotProgram p = Compile(RobotType.KUKA, b => { b.SpeedTo(0.0001); b.AccelerationTo(0.0001); b.MoveTo(300, 0, 300); });

        List<string> src = Lines(p, "src");
        Assert.Contains("  $VEL.CP = 0.000001", src);
        Assert.Contains("  $ACC.CP = 0.000001", src);
        Assert.DoesNotContain("  $VEL.CP = 0", src);
        Assert.Contains(p.Warnings, w => w.Instruction == "SpeedTo(0.0001);");
        Assert.Contains(p.Warnings, w => w.Instruction == "AccelerationTo(0.0001);");
    }

    [Theory]
    [InlineData(RobotType.MARLIN)]
    [InlineData(RobotType.ZMORPH)]
    public void GCode_FeedThatRoundsToZero_IsRaisedWithAWarning(RobotType brand)
    {
        RobotProgram p = Compile(brand, b => { b.SpeedTo(1e-6); b.MoveTo(300, 0, 300); });

        List<string> gcode = Lines(p, "gcode");
        Assert.Contains(gcode, l => l.Contains("F0.001", StringComparison.Ordinal));
        Assert.DoesNotContain(gcode, l => l.EndsWith(" F0", StringComparison.Ordinal) || l == "G1 F0");
        Assert.Contains(p.Warnings, w => w.Instruction == "SpeedTo(1E-06);");
    }

    [Fact]
    public void Marlin_AccelerationThatRoundsToZero_IsRaisedWithAWarning()
    {
        RobotProgram p = Compile(RobotType.MARLIN, b => b.AccelerationTo(0.0001));

        Assert.Contains("M204 P0.001 T0.001", Lines(p, "gcode"));
        Assert.Contains(p.Warnings, w => w.Instruction == "AccelerationTo(0.0001);");
    }

    [Theory]
    [InlineData(RobotType.MARLIN)]
    [InlineData(RobotType.ZMORPH)]
    public void GCode_HugeNumbers_AreNeverWrittenInExponentForm(RobotType brand)
    {
        RobotProgram p = Compile(brand, b =>
        {
            b.SpeedTo(1e6);
            b.AccelerationTo(1e6);
            b.TemperatureTo(1e6, RobotPartType.Bed);
            b.MoveTo(300, 0, 300);
        });

        List<string> gcode = Lines(p, "gcode");
        Assert.Contains("M190 S1000000", gcode);
        Assert.Contains(gcode, l => l.Contains("F60000000", StringComparison.Ordinal));
        Assert.DoesNotContain(gcode, l => !l.StartsWith(';') && l.Contains("E+", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData(RobotType.ABB, "mod", "    WaitTime 999999.999;")]
    [InlineData(RobotType.UR, "script", "  sleep(999999.999)")]
    public void LongestWait_IsWrittenWithoutExponent(RobotType brand, string extension, string expected)
    {
        RobotProgram p = Compile(brand, b => b.Wait(999_999_999));

        Assert.Contains(expected, Lines(p, extension));
    }

    [Theory]
    [InlineData("target1", "M_target1")]
    [InlineData("machina_acc_cp", "M_machina_acc_cp")]
    [InlineData("BAS", "M_BAS")]
    [InlineData("ir_stopm", "M_ir_stopm")]
    public void Krl_ProgramNamedLikeAGeneratedVariable_GetsAnotherModuleName(string robotName, string module)
    {
        RobotProgram p = Compile(RobotType.KUKA, b => { b.AccelerationTo(0); b.MoveTo(300, 0, 300); }, new CompileOptions { InlineTargets = false }, robotName);

        Assert.Equal([module + ".src", module + ".dat"], p.Files.Select(f => f.FileName));
        Assert.Contains("DEF " + module + "( )", Lines(p, "src"));
        Assert.Contains("DECL E6POS target1={X 300, Y 0, Z 300, A 180, B 0, C 180}", Lines(p, "dat"));
    }

    [Theory]
    [InlineData(RobotType.KUKA, "src")]
    [InlineData(RobotType.MARLIN, "gcode")]
    public void Comment_WithUnicodeLineSeparators_StaysOnOneLine(RobotType brand, string extension)
    {
        RobotProgram p = Compile(brand, b => b.Comment("a\u2028b\u2029c\u0085d"));

        Assert.Contains(Lines(p, extension), l => l.TrimStart() == "; a b c d");
    }

    [Theory]
    [InlineData(RobotType.MARLIN, "M117 a+b,c[d] e")]
    [InlineData(RobotType.ZMORPH, "M70 P1000 (a+b,c[d] e)")]
    public void GCode_MessageWithStarSemicolonParenthesesOrLineBreak_IsMadeSafeWithAWarning(RobotType brand, string expected)
    {
        RobotProgram p = Compile(brand, b => { b.Message("a*b;c(d)\ne"); b.Message("plain text"); });

        List<string> gcode = Lines(p, "gcode");
        Assert.Contains(expected, gcode);
        ProgramWarning warning = Assert.Single(p.Warnings);
        Assert.Equal("Message(\"a*b;c(d)\\ne\");", warning.Instruction);
        Assert.StartsWith("G-code messages cannot hold", warning.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Rapid_NamesOfDataTypesAndInstructions_AreNotUsedForModulesOrTools()
    {
        RobotProgram p = Compile(RobotType.ABB, b =>
        {
            b.DefineTool("MoveL", new Vector(0, 0, 100), Rotation.Identity);
            b.AttachTool("MoveL");
            b.MoveTo(300, 0, 300);
            b.DefineTool("tooldata", new Vector(0, 0, 50), Rotation.Identity);
            b.AttachTool("tooldata");
            b.MoveTo(300, 0, 200);
            b.WriteDigital("SetDO", true);
        }, name: "TPWrite");

        List<string> mod = Lines(p, "mod");
        Assert.Equal("MODULE TPWrite_2", mod[0]);
        Assert.Contains("  PERS tooldata MoveL_2 := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];", mod);
        Assert.Contains("  PERS tooldata tooldata_2 := [TRUE,[[0,0,50],[1,0,0,0]],[1,[0,0,25],[1,0,0,0],0,0,0]];", mod);
        Assert.Contains(mod, l => l.StartsWith("    MoveL ", StringComparison.Ordinal) && l.EndsWith(", MoveL_2\\WObj:=WObj0;", StringComparison.Ordinal));
        Assert.DoesNotContain(mod, l => l.Contains("SetDO SetDO", StringComparison.Ordinal));
        Assert.Contains(p.Warnings, w => w.Instruction == "WriteDigital(\"SetDO\",True);");
    }

    [Theory]
    [InlineData(RobotType.ABB)]
    [InlineData(RobotType.UR)]
    [InlineData(RobotType.MARLIN)]
    [InlineData(RobotType.HUMAN)]
    public void VeryLongRobotName_GivesAFileNameThatCanBeSaved(RobotType brand)
    {
        RobotProgram p = Compile(brand, b => b.MoveTo(300, 0, 300), name: new string('a', 300));
        string folder = Path.Combine(Path.GetTempPath(), "machina-longname-" + Guid.NewGuid().ToString("N"));
        try
        {
            IReadOnlyList<string> paths = p.SaveToFolder(folder);

            Assert.Equal(new string('a', 100), p.Name);
            Assert.All(p.Files, f => Assert.Equal(new string('a', 100), f.Name));
            Assert.All(paths, path => Assert.True(File.Exists(path)));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Theory]
    [InlineData("CON", "CON_")]
    [InlineData("nul", "nul_")]
    [InlineData("Com1", "Com1_")]
    [InlineData("Console", "Console")]
    public void WindowsDeviceName_IsNotUsedAsAFileName(string robotName, string programName)
    {
        RobotProgram p = Compile(RobotType.ABB, b => b.MoveTo(300, 0, 300), name: robotName);

        Assert.Equal(programName, p.Name);
        Assert.Equal([programName + ".pgf", programName + ".mod"], p.Files.Select(f => f.FileName));
    }
}
