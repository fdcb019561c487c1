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
}
