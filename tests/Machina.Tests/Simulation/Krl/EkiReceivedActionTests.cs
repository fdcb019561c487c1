using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// <see cref="EkiReceivedAction"/>: the virtual KUKA's request log keeps a received action's values and writes its text when the
/// log is first read: the text <see cref="EkiReceivedText"/> writes from the values, then the same string at every later read.
/// </summary>
public class EkiReceivedActionTests
{
    [Fact]
    public void Text_IsTheValuesAsAnElement_WrittenOnce()
    {
        (string Tag, string Value)[] values = [("DT/DR/A/@ID", "7"), ("DT/DR/A/@T", "1"), ("DT/DR/A/@M", "a&b \"c\" <d>")];
        var action = new EkiReceivedAction(values);
        var writer = new EkiReceivedText();

        string text = action.Text(writer);
        values[2] = ("DT/DR/A/@M", "changed"); // a second writing would show this

        Assert.Equal("<A ID=\"7\" T=\"1\" M=\"a&amp;b &quot;c&quot; &lt;d&gt;\"/>", text);
        Assert.Same(text, action.Text(new EkiReceivedText()));
    }
}
