using System.Collections;

namespace Machina;

/// <summary>
/// The actions of an instruction text that is read again from its start for every pass a compiler makes, so that no pass
/// holds the whole program: memory stays the same for ten lines or ten million. Actions get the ids a robot would give them
/// (1, 2, 3, … in order), and the source remembers where the action it returned last was written, for warnings and errors.
/// </summary>
internal sealed class InstructionSource(Func<TextReader> open, CancellationToken cancellationToken) : IEnumerable<RobotAction>
{
    private RobotAction? _current;
    private int _line;
    private int _column;

    /// <summary>Number of actions in the text, known after the first complete pass (0 before).</summary>
    internal int Count { get; private set; }

    /// <summary>The line of the action with id <paramref name="actionId"/> if it is the action returned last, else null.</summary>
    internal int? LineOf(int actionId) => _current is not null && _current.Id == actionId ? _line : null;

    /// <summary>The error for an action that cannot be applied: an instruction error at the action's position.</summary>
    internal InstructionParseException Refused(RobotAction action, string reason)
    {
        bool here = ReferenceEquals(action, _current);
        return new InstructionParseException(here ? _line : 0, here ? _column : 0, $"cannot apply \"{action.ToInstruction()}\": {reason}");
    }

    /// <inheritdoc/>
    public IEnumerator<RobotAction> GetEnumerator()
    {
        using TextReader reader = open();
        var parser = new InstructionReader(reader);
        int id = 0;
        while (parser.Next() is RobotAction action)
        {
            if ((id & 1023) == 0)
            {
                cancellationToken.ThrowIfCancellationRequested();
            }
            action.Id = ++id;
            _current = action;
            _line = parser.Line;
            _column = parser.Column;
            yield return action;
        }
        _current = null;
        Count = id;
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
