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
}
