using Machina.Tests.Support;

namespace Machina.Tests.Inputs;

/// <summary>ReadDigital / ReadAnalog: the action's text, its parsing, the exact native lines of every compiler and the online encodings.</summary>
public class ReadInputOfflineTests
{
    private static List<string> Lines(RobotType brand, string ext, Action<Robot> issue, out RobotProgram program)
    {
        program = TestCompile.Program(brand, issue);
        return [.. program.GetFile(ext)!.Lines];
    }

    [Fact]
    public void Action_TextAndDescription_AreExact()
    {
        Assert.Equal("ReadDigital(1);", new ActionReadInput("1", false, false).ToInstruction());
        Assert.Equal("ReadAnalog(\"AI_1\");", new ActionReadInput("AI_1", true, false).ToInstruction());
        Assert.Equal("ReadAnalog(0,True);", new ActionReadInput("0", true, true).ToInstruction());
        Assert.Equal("Read digital input \"DI_Part\"", new ActionReadInput("DI_Part", false, false).Describe());
        Assert.Equal("Read tool analog input 0", new ActionReadInput("0", true, true).Describe());
        Assert.Equal(28, (int)ActionType.ReadInput);
        Assert.Equal(ActionType.ReadInput, new ActionReadInput("1", false, false).Type);
    }

    [Theory]
    [InlineData("ReadDigital(1);")]
    [InlineData("ReadDigital(\"DI_Part\");")]
    [InlineData("ReadAnalog(0,True);")]
    public void Instruction_ParsesBackToTheSameAction(string text)
    {
        var action = (ActionReadInput)Assert.Single(Instructions.Parse(text));
        Assert.Equal(text, action.ToInstruction());
    }

    [Fact]
    public void Abb_DInputAndAInput_IntoDeclaredVariables_NumberedPinNotSupported()
    {
        List<string> lines = Lines(RobotType.ABB, "mod", bot =>
        {
            bot.ReadDigital("DI_Part");
            bot.ReadAnalog("AI_2");
            bot.ReadDigital(3);
        }, out RobotProgram p);

        Assert.Contains("  VAR dionum machina_di := 0;", lines);
        Assert.Contains("  VAR num machina_ai := 0;", lines);
        int i = lines.IndexOf("    machina_di := DInput(DI_Part);");
        Assert.True(i > 0, string.Join("\n", lines));
        Assert.Equal(["    machina_di := DInput(DI_Part);", "    machina_ai := AInput(AI_2);", "    ! NOT SUPPORTED ON ABB: Read digital input 3"], lines.GetRange(i, 3));
        Assert.True(lines.IndexOf("  VAR dionum machina_di := 0;") < lines.IndexOf("  PROC main()"));
        Assert.Equal("\"3\" is not a RAPID signal name; ABB signals are named in the controller's IO configuration (e.g. DO_1).", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void Abb_NoRead_NoDeclaration()
    {
        List<string> lines = Lines(RobotType.ABB, "mod", bot => bot.WriteDigital("DO_1", true), out _);
        Assert.DoesNotContain(lines, l => l.Contains("machina_di", StringComparison.Ordinal) || l.Contains("machina_ai", StringComparison.Ordinal));
    }

    [Fact]
    public void Ur_GetStandardAndToolInputs_OutOfRangeNotSupported()
    {
        List<string> lines = Lines(RobotType.UR, "script", bot =>
        {
            bot.ReadDigital(2);
            bot.ReadDigital(1, toolPin: true);
            bot.ReadAnalog(0);
            bot.ReadAnalog(1, toolPin: true);
            bot.ReadAnalog(2);
        }, out RobotProgram p);

        int i = lines.IndexOf("  machina_di = get_standard_digital_in(2)");
        Assert.True(i > 0, string.Join("\n", lines));
        Assert.Equal(
            ["  machina_di = get_standard_digital_in(2)",
             "  machina_di = get_tool_digital_in(1)",
             "  machina_ai = get_standard_analog_in(0)",
             "  machina_ai = get_tool_analog_in(1)",
             "  # NOT SUPPORTED ON UR: Read analog input 2"],
            lines.GetRange(i, 5));
        Assert.Equal("UR robots have standard analog inputs 0 to 1; input 2 does not exist.", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void Kuka_InAndAnin_IntoDeclaredVariables()
    {
        List<string> lines = Lines(RobotType.KUKA, "src", bot =>
        {
            bot.ReadDigital(5);
            bot.ReadDigital("DI_Part");
            bot.ReadAnalog(2);
        }, out RobotProgram p);

        Assert.Contains("  DECL BOOL machina_di", lines);
        Assert.Contains("  DECL REAL machina_ai", lines);
        Assert.True(lines.IndexOf("  DECL REAL machina_ai") < lines.IndexOf(";FOLD INI"), "declarations come before the first statement");
        int i = lines.IndexOf("  machina_di = $IN[5]");
        Assert.True(i > 0, string.Join("\n", lines));
        Assert.Equal(["  machina_di = $IN[5]", "  machina_di = DI_Part", "  machina_ai = $ANIN[2]"], lines.GetRange(i, 3));
        Assert.Empty(p.Warnings);
    }

    [Fact]
    public void Kuka_ToolPinAndOutOfRangeInputs_AreErrors()
    {
        Lines(RobotType.KUKA, "src", bot => { bot.ReadDigital(1, true); bot.ReadAnalog(33); bot.ReadDigital(4097); }, out RobotProgram p);

        Assert.Equal(
            ["KUKA controllers have no separate tool inputs; declare a SIGNAL for it in $config.dat and use its name.",
             "$ANIN inputs are numbered 1 to 32, so input 33 does not exist.",
             "$IN inputs are numbered 1 to 4096, so input 4097 does not exist."],
            p.Warnings.Select(w => w.Message));
    }

    [Theory]
    [InlineData(RobotType.ZMORPH)]
    [InlineData(RobotType.MARLIN)]
    public void GCode_NotApplicable(RobotType brand)
    {
        RobotProgram p = TestCompile.Program(brand, bot => bot.ReadAnalog(1));

        Assert.Contains("; ACTION \"Read analog input 1\" NOT APPLICABLE TO THIS DEVICE", p.Files[0].Lines);
        Assert.Equal("Machina's G-code programs do not read inputs.", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void OnlineEncoders_AbbRequests21And22_UrInstructions19And20_KukaActions15And16()
    {
        var cursor = new RobotCursor();
        var requests = new List<AbbRequest>();
        AbbActionEncoder.Encode(new ActionReadInput("DI_Door", false, false) { Id = 4 }, cursor, requests);
        AbbActionEncoder.Encode(new ActionReadInput("AI_1", true, false) { Id = 5 }, cursor, requests);
        Assert.Equal("@4 21 \"DI_Door\";@5 22 \"AI_1\";", string.Concat(requests.Select(r => r.ToWireText())));

        var values = new int[UrActionEncoder.MaxValues];
        Assert.Equal([7, 19, 1, 1], values[..UrActionEncoder.Encode(new ActionReadInput("1", false, true) { Id = 7 }, cursor, values)]);
        Assert.Equal([8, 20, 0, 0], values[..UrActionEncoder.Encode(new ActionReadInput("0", true, false) { Id = 8 }, cursor, values)]);
        Assert.Equal("\"Read tool digital input 2\" cannot be streamed to a UR robot: UR robots have tool digital inputs 0 to 1; input 2 does not exist.",
            UrActionEncoder.WhyNot(new ActionReadInput("2", false, true)));

        var xml = new System.Text.StringBuilder();
        KukaActionEncoder.Encode(new ActionReadInput("12", false, false), 9, cursor)!.Value.AppendTo(xml);
        KukaActionEncoder.Encode(new ActionReadInput("3", true, false), 10, cursor)!.Value.AppendTo(xml);
        Assert.Equal("<A ID=\"9\" T=\"15\" V1=\"12\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>"
            + "<A ID=\"10\" T=\"16\" V1=\"3\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", xml.ToString());
        Assert.Equal("ReadInput (ReadAnalog(33);) is not supported online on KUKA: $ANIN inputs are numbered 1 to 32, so input 33 does not exist.",
            KukaActionEncoder.WhyCannotStream(new ActionReadInput("33", true, false)));
    }

    [Fact]
    public void ReadDigitalAsync_Offline_IsRefusedWithoutIssuingAnything()
    {
        var bot = Robot.Create("T", "UR");
        var e = Assert.Throws<InvalidOperationException>(() => { _ = bot.ReadDigitalAsync(1); });
        Assert.Equal("Cannot wait for an input's value (offline, ReadDigital and ReadAnalog store it in the program) while the robot is offline; call ControlMode(\"online\") first.", e.Message);
        Assert.Empty(bot.GetProgramActions());
    }
}
