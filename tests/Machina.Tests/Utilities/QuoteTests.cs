using System.Text;

namespace Machina.Tests.Utilities;

/// <summary>Quoted instruction strings survive being saved as UTF-8 text.</summary>
public class QuoteTests
{
    [Fact]
    public void LoneSurrogate_IsEscapedSoThatAUtf8FileKeepsIt()
    {
        var message = new ActionMessage("a\uD83D b \uDE00 c 🤖");

        string text = message.ToInstruction();
        string saved = Encoding.UTF8.GetString(Encoding.UTF8.GetBytes(text));

        Assert.Equal("Message(\"a\\ud83d b \\ude00 c 🤖\");", text);
        Assert.Equal(message, Assert.Single(Instructions.Parse(saved)));
    }

    [Fact]
    public void UnicodeLineSeparators_AreEscapedSoTheListingKeepsOneStatementPerLine()
    {
        var message = new ActionMessage("a\u2028b\u2029c");

        string text = message.ToInstruction();

        Assert.Equal("Message(\"a\\u2028b\\u2029c\");", text);
        Assert.Equal(message, Assert.Single(Instructions.Parse(text)));
    }
}
