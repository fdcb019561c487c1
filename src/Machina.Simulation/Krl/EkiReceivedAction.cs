namespace Machina.Simulation.Krl;

/// <summary>
/// One action the virtual KUKA's driver channel received, as its request log keeps it: its values, written as the log's text
/// (<see cref="EkiReceivedText"/>) the first time someone reads the log, then kept as that text. A streamed action whose log
/// nobody reads costs an array of its value strings (the channel's own) instead of its text on the EKI reader's thread; its
/// tags are an array the actions before it with the same tags share. Not thread-safe: the controller reads it under its gate.
/// </summary>
internal sealed class EkiReceivedAction
{
    /// <summary>The tags, shared with the other actions that have the same ones; never written.</summary>
    private readonly string[] _tags;

    /// <summary>The values (a <c>string[]</c>, one per tag), then the text once written.</summary>
    private object _valuesOrText;

    private EkiReceivedAction(string[] tags, string[] values)
    {
        _tags = tags;
        _valuesOrText = values;
    }

    /// <summary>
    /// The action of <paramref name="action"/>'s values. Its tags are <paramref name="tags"/> when they are the same strings (the
    /// channel's splitter hands the same string for a tag each time), else a new array kept there for the next action.
    /// </summary>
    public static EkiReceivedAction Of(ReadOnlySpan<(string Tag, string Value)> action, ref string[]? tags)
    {
        string[]? shared = tags;
        if (shared is null || !HasTags(action, shared))
        {
            shared = new string[action.Length];
            for (int i = 0; i < shared.Length; i++)
            {
                shared[i] = action[i].Tag;
            }
            tags = shared;
        }
        var values = new string[action.Length];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = action[i].Value;
        }
        return new EkiReceivedAction(shared, values);
    }

    /// <summary>The action's log text (<c>&lt;A ID="1" …/&gt;</c>), written with <paramref name="writer"/> the first time.</summary>
    public string Text(EkiReceivedText writer)
    {
        if (_valuesOrText is not string text)
        {
            text = writer.Of(_tags, (string[])_valuesOrText);
            _valuesOrText = text;
        }
        return text;
    }

    /// <summary>True when <paramref name="action"/>'s tags are <paramref name="tags"/>' strings, in order.</summary>
    private static bool HasTags(ReadOnlySpan<(string Tag, string Value)> action, string[] tags)
    {
        if (action.Length != tags.Length)
        {
            return false;
        }
        for (int i = 0; i < tags.Length; i++)
        {
            if (!ReferenceEquals(action[i].Tag, tags[i]))
            {
                return false;
            }
        }
        return true;
    }
}
