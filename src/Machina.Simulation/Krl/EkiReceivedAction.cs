namespace Machina.Simulation.Krl;

/// <summary>
/// One action the virtual KUKA's driver channel received, as its request log keeps it: its values, written as the log's text
/// (<see cref="EkiReceivedText"/>) the first time someone reads the log, then kept as that text. A streamed action whose log
/// nobody reads costs the copy of its values (their strings are the channel's own) instead of its text on the EKI reader's
/// thread. Not thread-safe: the controller reads it under its gate.
/// </summary>
/// <param name="values">The action's values, from its ID to the next action's.</param>
internal sealed class EkiReceivedAction((string Tag, string Value)[] values)
{
    private (string Tag, string Value)[]? _values = values;
    private string? _text;

    /// <summary>The action's log text (<c>&lt;A ID="1" …/&gt;</c>), written with <paramref name="writer"/> the first time.</summary>
    public string Text(EkiReceivedText writer)
    {
        if (_text is null)
        {
            _text = writer.Of(_values);
            _values = null;
        }
        return _text;
    }
}
