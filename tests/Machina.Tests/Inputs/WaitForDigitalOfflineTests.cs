using Machina.Tests.Support;

namespace Machina.Tests.Inputs;

/// <summary>WaitForDigital: the action's text, its parsing, and the exact native lines of every compiler.</summary>
public class WaitForDigitalOfflineTests
{
    private static List<string> Lines(RobotType brand, string ext, Action<Robot> issue, out RobotProgram program)
    {
        program = TestCompile.Program(brand, issue);
        return [.. program.GetFile(ext)!.Lines];
    }

    /// <summary>The lines from the first that starts with <paramref name="first"/> (after its indent), <paramref name="count"/> of them.</summary>
    private static List<string> From(List<string> lines, string first, int count)
    {
        int i = lines.FindIndex(l => l.TrimStart().StartsWith(first, StringComparison.Ordinal));
        Assert.True(i >= 0, $"no line starts with {first}:\n{string.Join("\n", lines)}");
        return lines.GetRange(i, count);
    }

    [Fact]
    public void Action_TextAndDescription_AreExact()
    {
        Assert.Equal("WaitForDigital(1,True);", new ActionWaitDigital("1", true, 0, false).ToInstruction());
        Assert.Equal("WaitForDigital(\"DI_Part\",False,2500);", new ActionWaitDigital("DI_Part", false, 2500, false).ToInstruction());
        Assert.Equal("WaitForDigital(0,True,0,True);", new ActionWaitDigital("0", true, 0, true).ToInstruction());
        Assert.Equal("Wait for digital input \"DI_Part\" OFF (at most 2500 ms)", new ActionWaitDigital("DI_Part", false, 2500, false).Describe());
        Assert.Equal("Wait for tool digital input 0 ON", new ActionWaitDigital("0", true, 0, true).Describe());
        Assert.Equal(ActionType.WaitDigital, new ActionWaitDigital("1", true, 0, false).Type);
        Assert.Equal(27, (int)ActionType.WaitDigital);
    }

    [Theory]
    [InlineData("WaitForDigital(1,True);")]
    [InlineData("WaitForDigital(\"DI_Part\",False,2500);")]
    [InlineData("WaitForDigital(0,True,0,True);")]
    public void Instruction_ParsesBackToTheSameAction(string text)
    {
        var action = (ActionWaitDigital)Assert.Single(Instructions.Parse(text));
        Assert.Equal(text, action.ToInstruction());
    }

    [Fact]
    public void NegativeTimeout_IsRefusedWithItsReason()
    {
        var bot = Robot.Create("T", "ABB");
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => bot.WaitForDigital("DI_1", true, -1));
        Assert.Equal("timeoutMillis", e.ParamName);
        Assert.StartsWith("A wait's time limit cannot be negative; give milliseconds, or 0 to wait as long as it takes.", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Abb_WaitDI_WithAndWithoutMaxTime_NumberedPinNotSupported()
    {
        List<string> lines = Lines(RobotType.ABB, "mod", bot =>
        {
            bot.WaitForDigital("DI_Part", true);
            bot.WaitForDigital("DI_Door", false, 2500);
            bot.WaitForDigital(3, true);
        }, out RobotProgram p);

        Assert.Equal(["    WaitDI DI_Part, 1;", "    WaitDI DI_Door, 0\\MaxTime:=2.5;", "    ! NOT SUPPORTED ON ABB: Wait for digital input 3 ON"], From(lines, "WaitDI", 3));
        Assert.Equal("\"3\" is not a RAPID signal name; ABB signals are named in the controller's IO configuration (e.g. DO_1).", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void Ur_LoopOnTheInput_WithATimedHaltWhenLimited()
    {
        List<string> lines = Lines(RobotType.UR, "script", bot =>
        {
            bot.WaitForDigital(2, true);
            bot.WaitForDigital(1, false, 1500, toolPin: true);
            bot.WaitForDigital(8, true);
        }, out RobotProgram p);

        Assert.Equal(
            ["  while get_standard_digital_in(2) != True:",
             "    sync()",
             "  end",
             "  machina_waited = 0",
             "  while get_tool_digital_in(1) != False:",
             "    if machina_waited >= 1.5:",
             "      popup(\"Tool digital input 1 did not turn off within 1.5 s\", \"Machina\", error=True)",
             "      halt",
             "    end",
             "    sync()",
             "    machina_waited = machina_waited + get_steptime()",
             "  end",
             "  # NOT SUPPORTED ON UR: Wait for digital input 8 ON"],
            From(lines, "while get_standard_digital_in(2)", 13));
        Assert.Equal("UR robots have standard digital inputs 0 to 7; input 8 does not exist.", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void Kuka_WaitFor_WithTimer15AndHaltWhenLimited()
    {
        List<string> lines = Lines(RobotType.KUKA, "src", bot =>
        {
            bot.WaitForDigital(5, true);
            bot.WaitForDigital("DI_Part", false);
            bot.WaitForDigital(6, true, 2000);
        }, out RobotProgram p);

        Assert.Equal(
            ["  WAIT FOR $IN[5]",
             "  WAIT FOR NOT DI_Part",
             "  $TIMER[15] = 0",
             "  $TIMER_STOP[15] = FALSE",
             "  WAIT FOR $IN[6] OR ($TIMER[15] >= 2000)",
             "  $TIMER_STOP[15] = TRUE",
             "  IF NOT $IN[6] THEN",
             "    HALT ; Wait for digital input 6 ON (at most 2000 ms): timed out",
             "  ENDIF"],
            From(lines, "WAIT FOR $IN[5]", 9));
        Assert.Empty(p.Warnings);
    }

    [Fact]
    public void Kuka_ToolPinAndOutOfRangeInput_AreErrors()
    {
        Lines(RobotType.KUKA, "src", bot => { bot.WaitForDigital(1, true, 0, true); bot.WaitForDigital(4097, true); }, out RobotProgram p);

        Assert.Equal(
            ["KUKA controllers have no separate tool inputs; declare a SIGNAL for it in $config.dat and use its name.",
             "$IN inputs are numbered 1 to 4096, so input 4097 does not exist."],
            p.Warnings.Select(w => w.Message));
    }

    [Theory]
    [InlineData(RobotType.ZMORPH)]
    [InlineData(RobotType.MARLIN)]
    public void GCode_NotApplicable(RobotType brand)
    {
        RobotProgram p = TestCompile.Program(brand, bot => bot.WaitForDigital(1, true));

        Assert.Contains("; ACTION \"Wait for digital input 1 ON\" NOT APPLICABLE TO THIS DEVICE", p.Files[0].Lines);
        Assert.Equal("Machina's G-code programs do not wait for inputs.", Assert.Single(p.Warnings).Message);
    }

    [Fact]
    public void OnlineEncoders_AbbRequest20_UrInstruction18_KukaAction14()
    {
        var cursor = new RobotCursor();
        var wait = new ActionWaitDigital("DI_Door", false, 2500, false) { Id = 4 };
        Assert.Null(cursor.TryApply(wait));
        var requests = new List<AbbRequest>();
        AbbActionEncoder.Encode(wait, cursor, requests);
        Assert.Equal("@4 20 \"DI_Door\" 0 2.5;", string.Concat(requests.Select(r => r.ToWireText())));

        var ur = new ActionWaitDigital("1", true, 1500, true) { Id = 7 };
        var values = new int[UrActionEncoder.MaxValues];
        Assert.Equal([7, 18, 1, 1, 1, 1500], values[..UrActionEncoder.Encode(ur, cursor, values)]);
        Assert.Equal("\"Wait for digital input 9 ON\" cannot be streamed to a UR robot: UR robots have standard digital inputs 0 to 7; input 9 does not exist.",
            UrActionEncoder.WhyNot(new ActionWaitDigital("9", true, 0, false)));

        KukaInstruction kuka = KukaActionEncoder.Encode(new ActionWaitDigital("12", true, 2000, false), 9, cursor)!.Value;
        var xml = new System.Text.StringBuilder();
        kuka.AppendTo(xml);
        Assert.Equal("<A ID=\"9\" T=\"14\" V1=\"12\" V2=\"1\" V3=\"2000\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", xml.ToString());
        Assert.Equal("WaitDigital (WaitForDigital(\"DI_Part\",True);) is not supported online on KUKA: the driver reads inputs by number ($IN[1] to $IN[4096]); a signal name such as \"DI_Part\" exists only in the controller's configuration.",
            KukaActionEncoder.WhyCannotStream(new ActionWaitDigital("DI_Part", true, 0, false)));
    }
}
