namespace Machina.Simulation.Krl;

/// <summary>
/// One action the virtual KUKA's driver channel received, as its request log keeps it until the log is first read: its values,
/// which the log then writes as its text (<see cref="EkiReceivedText"/>) and keeps in the action's place. A streamed action whose
/// log nobody reads costs an array of its value strings (the channel's own) instead of its text on the EKI reader's thread; its
/// tags are an array the actions before it with the same tags share. Never written once made.
/// </summary>
internal sealed class EkiReceivedAction
{
    /// <summary>The tags, shared with the other actions that have the same ones.</summary>
    private readonly string[] _tags;

    /// <summary>The values, one per tag.</summary>
    private readonly string[] _values;

    private EkiReceivedAction(string[] tags, string[] values)
    {
        _tags = tags;
        _values = values;
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

    /// <summary>The action's log text (<c>&lt;A ID="1" …/&gt;</c>), written with <paramref name="writer"/> (the log keeps it).</summary>
    public string Text(EkiReceivedText writer) => writer.Of(_tags, _values);

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
