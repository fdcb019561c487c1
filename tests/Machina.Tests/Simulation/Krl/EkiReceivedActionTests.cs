using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// <see cref="EkiReceivedAction"/>: the virtual KUKA's request log keeps a received action's values until the log is first read,
/// when it writes the text <see cref="EkiReceivedText"/> writes from the values and keeps that text in the action's place (the
/// log's part: <c>EkiSeamReceivedLogTests</c>, <c>RequestLogTextWrittenOnceTests</c>); actions with the same tag strings share
/// one array of tags.
/// </summary>
public class EkiReceivedActionTests
{
    private const string Id = "DT/DR/A/@ID", Type = "DT/DR/A/@T", Message = "DT/DR/A/@M";

    [Fact]
    public void Text_IsTheValuesAsAnElement_FromTheValuesCopiedWhenMade()
    {
        (string Tag, string Value)[] values = [(Id, "7"), (Type, "1"), (Message, "a&b \"c\" <d>")];
        string[]? tags = null;
        EkiReceivedAction action = EkiReceivedAction.Of(values, ref tags);
        values[2] = (Message, "changed"); // the action copied the values it was given

        string text = action.Text(new EkiReceivedText());

        Assert.Equal("<A ID=\"7\" T=\"1\" M=\"a&amp;b &quot;c&quot; &lt;d&gt;\"/>", text);
        Assert.Equal(text, action.Text(new EkiReceivedText())); // the action is never written: the same values, the same text
        Assert.Equal([Id, Type, Message], tags!);
    }

    [Fact]
    public void ActionsWithTheSameTagStrings_ShareTheirTags_AndOthersGetTheirOwn()
    {
        string[]? tags = null;
        EkiReceivedAction first = EkiReceivedAction.Of([(Id, "1"), (Type, "3")], ref tags);
        string[]? kept = tags;
        EkiReceivedAction second = EkiReceivedAction.Of([(Id, "2"), (Type, "4")], ref tags);
        Assert.Same(kept, tags);

        string otherType = new([.. Type]); // equal characters, another string: not the splitter's tag
        EkiReceivedAction third = EkiReceivedAction.Of([(Id, "5"), (otherType, "6"), (Message, "")], ref tags);
        Assert.NotSame(kept, tags);
        Assert.Same(otherType, tags![1]);

        var writer = new EkiReceivedText();
        Assert.Equal(
            ["<A ID=\"1\" T=\"3\"/>", "<A ID=\"2\" T=\"4\"/>", "<A ID=\"5\" T=\"6\" M=\"\"/>"],
            [first.Text(writer), second.Text(writer), third.Text(writer)]);
    }
}
