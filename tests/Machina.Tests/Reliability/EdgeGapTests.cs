namespace Machina.Tests.Reliability;

/// <summary>Edges that mutation testing showed no test pinned down: each asserts the exact output.</summary>
public class EdgeGapTests
{
    private static List<string> Body(Robot bot, RobotType language)
    {
        var lines = bot.Compile(language, new CompileOptions { HumanComments = false }).Files[0].Lines.ToList();
        return lines.Skip(lines.IndexOf("G92 E0") + 2).ToList();
    }

    [Theory]
    [InlineData(RobotType.ZMORPH, "G1 F1200", "G1 X0 Y0 Z1")]
    [InlineData(RobotType.MARLIN, null, "G0 X0 Y0 Z1 F1200")]
    public void TemperatureToZeroAndExtrusionRateToZero_GCode_WriteZeroes(RobotType language, string? feed, string firstMove)
    {
        var bot = Robot.Create("T", language);
        bot.TemperatureTo(0, "extruder");
        bot.TemperatureTo(0, "bed", false);
        bot.ExtrusionRateTo(0);
        bot.MoveTo(0, 0, 1);
        bot.Extrude();
        bot.Move(10, 0, 0);

        string[] expected = ["M109 S0", "M140 S0", .. feed is null ? Array.Empty<string>() : [feed], firstMove, "G1 X10 Y0 Z1 E0"];
        Assert.Equal(expected, Body(bot, language));
    }

    [Fact]
    public void LastAction_RobotWithModel_IsTheLastMotion()
    {
        var bot = Robot.Create("M", "ABB", "IRB 120");
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.Move(10, 0, 0);

        Assert.Equal("Move(10,0,0);", bot.GetCurrentState().LastAction?.ToInstruction());
        bot.SpeedTo(20);
        Assert.Equal("SpeedTo(20);", bot.GetCurrentState().LastAction?.ToInstruction());
    }

    [Fact]
    public void Kuka_ExternalAxisSix_AnalogAtBothLimits_AndOutput4096_AreWritten()
    {
        var bot = Robot.Create("K", RobotType.KUKA);
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.ExternalAxisTo(6, 25);
        bot.AxesTo(0, 0, 0, 0, 80, 0);
        bot.WriteAnalog(1, 1);
        bot.WriteAnalog(2, -1);
        bot.WriteDigital(4096, true);
        bot.WriteDigital(4097, true);
        bot.WriteAnalog(3, 1.0000001);

        var lines = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false }).Files[0].Lines.ToList();
        int start = lines.IndexOf("  PTP {AXIS: A1 0, A2 0, A3 0, A4 0, A5 90, A6 0} C_PTP");
        Assert.Equal(
            [
                "  PTP {E6AXIS: A1 0, A2 0, A3 0, A4 0, A5 80, A6 0, E6 25} C_PTP",
                "  $ANOUT[1] = 1",
                "  $ANOUT[2] = -1",
                "  $OUT[4096] = TRUE",
                "  ; ERROR on \"Turn digital IO 4097 ON\": $OUT outputs are numbered 1 to 4096, so output 4097 does not exist.",
                "  ; ERROR on \"Set analog IO 3 to 1.0000001\": KRL analog outputs take values from -1 to 1, and 1.0000001 is outside that range.",
            ],
            lines.GetRange(start + 1, 6));
    }

    [Theory]
    [InlineData("MoveTo(", 1, 8, "MoveTo( is not closed with ')'.")]
    [InlineData("Wait(1); Speed(", 1, 16, "Speed( is not closed with ')'.")]
    public void Parse_TextEndingRightAfterTheParenthesis_IsNotClosed(string text, int line, int column, string problem)
    {
        var e = Assert.Throws<InstructionParseException>(() => Instructions.Parse(text));

        Assert.Equal((line, column, problem), (e.Line, e.Column, e.Problem));
    }

    [Fact]
    public void Parse_MoreThanTwentyArguments_SaysHowManyAndTheForms()
    {
        var e = Assert.Throws<InstructionParseException>(() => Instructions.Parse("ArcMotionTo(" + string.Join(",", Enumerable.Range(1, 21)) + ");"));

        Assert.Equal((1, 1), (e.Line, e.Column));
        Assert.Equal("ArcMotionTo was given 21 arguments; use it as ArcMotionTo(throughX, throughY, throughZ, endX, endY, endZ) or "
            + "ArcMotionTo(through origin, X axis, Y axis, end origin, X axis, Y axis: 18 numbers).", e.Problem);
        Assert.Equal("MoveTo was given 22 arguments; use it as MoveTo(x, y, z).",
            Assert.Throws<InstructionParseException>(() => Instructions.Parse("MoveTo(" + string.Join(",", Enumerable.Range(1, 22)) + ");")).Problem);
    }

    [Fact]
    public void Parse_IntegerAboveTwoToThe31_IsALongWhereLongsFit_AndRefusedWhereIntsAreExpected()
    {
        Assert.Equal(2_147_483_648L, ((ActionWait)Assert.Single(Instructions.Parse("Wait(2147483648);"))).Millis);
        Assert.Equal("2147483648", ((ActionIODigital)Assert.Single(Instructions.Parse("WriteDigital(2147483648, true);"))).PinName);

        var e = Assert.Throws<InstructionParseException>(() => Instructions.Parse("ExternalAxisTo(2147483648, 1);"));
        Assert.Equal((1, 16, "argument 1 of ExternalAxisTo is too large."), (e.Line, e.Column, e.Problem));
        var beyondLong = Assert.Throws<InstructionParseException>(() => Instructions.Parse("Wait(9223372036854775808);"));
        Assert.Equal("argument 1 of Wait must be a whole number (like 2000), but it is \"9223372036854775808\".", beyondLong.Problem);
    }
}
