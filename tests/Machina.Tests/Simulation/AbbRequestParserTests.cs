using Machina.Simulation;

namespace Machina.Tests.Simulation;

public class AbbRequestParserTests
{
    [Fact]
    public void TryParse_EncodedRequest_RoundTripsEveryField()
    {
        var original = AbbRequest.Tool(19, new Vector(1.5, -2, 100), Rotation.Identity, 2.25, new Vector(0, 0, 50));
        string wire = original.ToWireText();
        Assert.True(AbbRequestParser.TryParse(wire.AsSpan(0, wire.Length - 1), out var parsed, out var error), error);
        Assert.Equal(19, parsed.Id);
        Assert.Equal(8, parsed.Code);
        Assert.Equal(11, parsed.ParameterCount);
        Assert.Equal([1.5, -2, 100, 1, 0, 0, 0, 2.25, 0, 0, 50], Enumerable.Range(0, 11).Select(i => parsed[i]).ToArray());
    }

    [Fact]
    public void TryParse_TextParameter_IsReadBetweenQuotes()
    {
        Assert.True(AbbRequestParser.TryParse("@21 10 \"DO 15\" 1", out var parsed, out _));
        Assert.Equal("DO 15", parsed.Text);
        Assert.Equal(1, parsed[0]);
        Assert.Equal(0, parsed[5]);
    }

    [Fact]
    public void TryParse_NoIdPrefix_IdIsZero()
    {
        Assert.True(AbbRequestParser.TryParse("4 100", out var parsed, out _));
        Assert.Equal((0, 4, 100.0), (parsed.Id, parsed.Code, parsed[0]));
    }

    [Theory]
    [InlineData("@x 1 2", "corrupt id")]
    [InlineData("@1 move 2", "corrupt message")]
    [InlineData("@1 1 2 abc", "corrupt parameter")]
    [InlineData("@1 7 \"unterminated", "closing quote")]
    [InlineData("@1 17 1 2 3 4 5 6 7 8 9 10 11 12", "more than 11")]
    [InlineData("@1\0 4 100", "control character")]
    [InlineData("@1 4 100\0", "control character")]
    [InlineData("@1 4\u0001 100", "control character")]
    [InlineData("@1 7 \"a\0b\"", "control character")]
    public void TryParse_Malformed_ReturnsReason(string statement, string reason)
    {
        Assert.False(AbbRequestParser.TryParse(statement, out _, out var error));
        Assert.Contains(reason, error, StringComparison.Ordinal);
    }
}
