namespace Machina.Tests.Programs;

/// <summary>
/// Behaviour of the instruction parser that the other tests left unchecked (found by mutation testing, tests/mutation/run.sh
/// parser): escapes inside quoted numbers and booleans, a backslash at the very end of a text, and the edges of 32-bit arguments.
/// </summary>
public class InstructionParserMutationGapTests
{
    private static InstructionParseException ParseError(string text) => Assert.Throws<InstructionParseException>(() => Instructions.Parse(text));

    [Fact]
    public void Parse_QuotedNumberAndBooleanWithEscapes_UseTheUnescapedText()
    {
        var actions = Instructions.Parse("SpeedTo(\"1\\u0030\"); Extrude(\"tru\\u0065\");");

        Assert.Equal(10, ((ActionSpeed)actions[0]).Speed);
        Assert.True(((ActionExtrusion)actions[1]).Extrude);
    }

    [Theory]
    [InlineData("a\\", "a\\")]        // a lone backslash at the end is kept
    [InlineData("\\", "\\")]
    [InlineData("a\\qb", "a\\qb")]    // an unknown escape is kept as it is
    [InlineData("a\\\\", "a\\")]
    public void Unescape_BackslashAtTheEndOrUnknown_IsKept(string body, string expected) =>
        Assert.Equal(expected, InstructionArgs.Unescape(body));

    [Theory]
    [InlineData("2147483647")]
    [InlineData("-2147483648")]
    public void Parse_AxisNumberAtTheEdgesOf32Bits_IsRefusedAsAnAxisNotAsTooLarge(string number)
    {
        var ex = ParseError($"ExternalAxisTo({number}, 1);");

        Assert.Equal("ExternalAxisTo: External axis numbers are 1 to 6.", ex.Problem);
    }

    // How each instruction is used, as the error for a wrong number of arguments tells a user: written out here on purpose,
    // so that a usage lost or garbled in the catalogue fails.
    [Theory]
    [InlineData("Speed", 2, "Speed(increment)")]
    [InlineData("SpeedTo", 2, "SpeedTo(mmPerSecond)")]
    [InlineData("Acceleration", 2, "Acceleration(increment)")]
    [InlineData("AccelerationTo", 2, "AccelerationTo(mmPerSecondSquared)")]
    [InlineData("Precision", 2, "Precision(increment)")]
    [InlineData("PrecisionTo", 2, "PrecisionTo(radius)")]
    [InlineData("MotionMode", 2, "MotionMode(\"linear\"|\"joint\")")]
    [InlineData("Coordinates", 2, "Coordinates(\"world\"|\"local\")")]
    [InlineData("PushSettings", 1, "PushSettings()")]
    [InlineData("PopSettings", 1, "PopSettings()")]
    [InlineData("Move", 4, "Move(x, y[, z])")]
    [InlineData("MoveTo", 4, "MoveTo(x, y, z)")]
    [InlineData("Rotate", 5, "Rotate(axisX, axisY, axisZ, degrees)")]
    [InlineData("RotateTo", 7, "RotateTo(xAxisX, xAxisY, xAxisZ, yAxisX, yAxisY, yAxisZ)")]
    [InlineData("Transform", 9, "Transform(x, y, z, axisX, axisY, axisZ, degrees[, translationFirst])")]
    [InlineData("TransformTo", 10, "TransformTo(x, y, z, xAxisX, xAxisY, xAxisZ, yAxisX, yAxisY, yAxisZ)")]
    [InlineData("ArcMotion", 7, "ArcMotion(throughX, throughY, throughZ, endX, endY, endZ)")]
    [InlineData("ArcMotionTo", 19, "ArcMotionTo(throughX, throughY, throughZ, endX, endY, endZ) or ArcMotionTo(through origin, X axis, Y axis, end origin, X axis, Y axis: 18 numbers)")]
    [InlineData("Axes", 7, "Axes(j1, j2, j3, j4, j5, j6)")]
    [InlineData("AxesTo", 7, "AxesTo(j1, j2, j3, j4, j5, j6)")]
    [InlineData("ExternalAxis", 4, "ExternalAxis(axisNumber, increment[, \"all\"|\"cartesian\"|\"joint\"])")]
    [InlineData("ExternalAxisTo", 4, "ExternalAxisTo(axisNumber, value[, \"all\"|\"cartesian\"|\"joint\"])")]
    [InlineData("ArmAngle", 2, "ArmAngle(increment)")]
    [InlineData("ArmAngleTo", 2, "ArmAngleTo(degrees)")]
    [InlineData("Wait", 2, "Wait(milliseconds)")]
    [InlineData("Message", 2, "Message(\"text\")")]
    [InlineData("Comment", 2, "Comment(\"text\")")]
    [InlineData("CustomCode", 3, "CustomCode(\"statement\"[, isDeclaration])")]
    [InlineData("DefineTool", 15, "DefineTool(\"name\", tipX, tipY, tipZ, xAxisX, xAxisY, xAxisZ, yAxisX, yAxisY, yAxisZ, weightKg, cogX, cogY, cogZ)")]
    [InlineData("AttachTool", 2, "AttachTool(\"name\")")]
    [InlineData("DetachTool", 1, "DetachTool()")]
    [InlineData("WriteDigital", 4, "WriteDigital(pin, on[, toolPin])")]
    [InlineData("WriteAnalog", 4, "WriteAnalog(pin, value[, toolPin])")]
    [InlineData("Temperature", 4, "Temperature(increment, \"extruder\"|\"bed\"|\"chamber\"[, wait])")]
    [InlineData("TemperatureTo", 4, "TemperatureTo(celsius, \"extruder\"|\"bed\"|\"chamber\"[, wait])")]
    [InlineData("ExtrusionRate", 2, "ExtrusionRate(increment)")]
    [InlineData("ExtrusionRateTo", 2, "ExtrusionRateTo(mmPerMm)")]
    [InlineData("Extrude", 2, "Extrude([on])")]
    [InlineData("Initialize", 1, "Initialize()")]
    [InlineData("Terminate", 1, "Terminate()")]
    public void Parse_TooManyArguments_ErrorShowsEveryUsage(string name, int count, string usages)
    {
        string args = string.Join(", ", Enumerable.Repeat("1", count));

        var ex = ParseError($"{name}({args});");

        string given = count == 1 ? "1 argument" : $"{count} arguments";
        Assert.Equal($"{name} was given {given}; use it as {usages}.", ex.Problem);
    }

    [Fact]
    public void Parse_TransformWithoutItsLastArgument_TranslatesFirst()
    {
        var relative = (ActionTransformation)Assert.Single(Instructions.Parse("Transform(1, 2, 3, 0, 0, 1, 90);"));
        var absolute = (ActionTransformation)Assert.Single(Instructions.Parse("TransformTo(1, 2, 3, 1, 0, 0, 0, 1, 0);"));

        Assert.True(relative.TranslationFirst);
        Assert.True(absolute.TranslationFirst);
        Assert.False(((ActionTransformation)Instructions.Parse("Transform(1, 2, 3, 0, 0, 1, 90, false);")[0]).TranslationFirst);
    }

    [Fact]
    public void Parse_CommentAndMessageWithoutText_AreEmptyNotTheLastText()
    {
        var actions = Instructions.Parse("Comment(\"x\"); Comment(); Message(\"y\"); Message();");

        Assert.Equal(["x", ""], actions.OfType<ActionComment>().Select(c => c.Comment));
        Assert.Equal(["y", ""], actions.OfType<ActionMessage>().Select(m => m.Message));
    }

    [Theory]
    [InlineData("ExternalAxisTo(1, 5, \"both\");", "\"both\" is not a valid external axes target; use one of: All, Cartesian, Joint.")]
    [InlineData("TemperatureTo(200, \"nozzle\");", "\"nozzle\" is not a valid printer part; use one of: Extruder, Bed, Chamber.")]
    [InlineData("Coordinates(\"tool\");", "\"tool\" is not a valid coordinate system; use one of: World, Local.")]
    [InlineData("MotionMode(\"circular\");", "\"circular\" is not a valid motion type; use one of: Linear, Joint.")]
    public void Parse_UnknownChoice_ErrorNamesWhatWasExpected(string text, string problem) => Assert.Equal(problem, ParseError(text).Problem);

    [Theory]
    [InlineData("Wait", 1, 5)]
    [InlineData("SpeedTo(10); Wait  ", 1, 20)]
    public void Parse_TextEndingAfterAName_AsksForTheParenthesis(string text, int line, int column)
    {
        var ex = ParseError(text);

        Assert.Equal((line, column), (ex.Line, ex.Column));
        Assert.Equal("expected '(' after Wait.", ex.Problem);
    }

    [Fact]
    public void Parse_NoArgumentsWithSpacesOrACommentInside_TakesNoArguments()
    {
        var actions = Instructions.Parse("PushSettings( ); PopSettings( // restore\n);");

        Assert.Equal([true, false], actions.Cast<ActionPushPop>().Select(a => a.Push));
    }

    [Theory]
    [InlineData("Message(\"abc")]
    [InlineData("Message(\"abc\\")]
    [InlineData("Message(\"abc\\\ndef\")")]  // a backslash before a line break escapes nothing
    public void Parse_TextEndingInsideAString_SaysTheStringIsNotClosed(string text)
    {
        var ex = ParseError(text);

        Assert.Equal((1, 9), (ex.Line, ex.Column));
        Assert.Equal("this text is not closed with a double quote (\"); write a quote inside text as \\\".", ex.Problem);
    }

    [Fact]
    public void Parse_EmptyArgumentAfterASpace_IsAMissingValue()
    {
        var ex = ParseError("MoveTo(1, , 3);");

        Assert.Equal((1, 11), (ex.Line, ex.Column));
        Assert.Equal("a value is missing in MoveTo(...).", ex.Problem);
    }

    [Theory]
    [InlineData("Wait(1); /", "expected an instruction such as MoveTo(400, 300, 500), but found '/'.")]
    [InlineData("Wait(1); a/b", "unknown instruction \"a\".")]
    public void Parse_SingleSlash_IsNotAComment(string text, string problem)
    {
        var ex = ParseError(text);

        Assert.Equal((1, 10), (ex.Line, ex.Column));
        Assert.Equal(problem, ex.Problem);
    }
}
