namespace Machina.Tests.Utilities;

public sealed class PrintableTextTests
{
    [Theory]
    [InlineData("plain text, été, 日本", "plain text, été, 日本")]
    [InlineData("\u001b[2J\u001b]0;title\u0007", "\\x1b[2J\\x1b]0;title\\x07")]
    [InlineData("a\r\nb\tc\u007f\u009b", "a\\r\\nb\\tc\\x7f\\x9b")]
    [InlineData("abc\u202edef\u2066", "abc\\u202edef\\u2066")]
    public void Of_WritesWhatATerminalActsOnAsEscapes(string text, string expected) =>
        Assert.Equal(expected, PrintableText.Of(text));

    [Fact]
    public void Of_KeepingLines_KeepsLineFeedsAndTabs_EscapesTheRest() =>
        Assert.Equal("one\n\ttwo\\r\\x1b[0m", PrintableText.Of("one\n\ttwo\r\u001b[0m", keepLines: true));
}
