using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes a whole <c>MoveL</c>/<c>MoveJ</c> line with an inline robtarget into one reused array, as <see cref="RapidWriter"/>
/// writes it through a builder: the position's three numbers, then the text after it (orientation, configuration, external
/// axes, speed, zone, tool and the comment's start) kept while all of it stays the same, then the move's description. A
/// toolpath changes only its position from move to move, so one copy replaces a dozen appends to a builder.
/// </summary>
internal sealed class RapidMoveLine
{
    /// <summary>The inline targets' kept text, shared with the writer's other lines (arcs).</summary>
    internal RapidTargetText Targets { get; } = new();

    private readonly StringBuilder _restText = new(192);
    private char[] _line = new char[256];
    private char[] _rest = [];
    private bool _known;
    private int _tail;
    private string? _speed, _zone, _tool;

    /// <summary>
    /// Writes <paramref name="start"/> (indent and instruction) and the inline target (<paramref name="tail"/>: the text after its
    /// position, from <see cref="RapidTargetText.Tail"/> of the same targets), speed, zone, tool and, with
    /// <paramref name="human"/>, the action's comment into <paramref name="sink"/> as one line; false (nothing written) when a
    /// coordinate is too large for the fast digits, and the caller writes the line the general way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal bool TryWrite(LineSink sink, string start, Vector position, StringBuilder tail, string speed, string zone, string tool,
                           RobotAction action, bool human)
    {
        if (!_known || Targets.Version != _tail || !ReferenceEquals(speed, _speed) || !ReferenceEquals(zone, _zone)
            || !ReferenceEquals(tool, _tool))
        {
            _restText.Clear().Append(tail).Append(", ").Append(speed).Append(", ").Append(zone).Append(", ").Append(tool)
                     .Append("\\WObj:=WObj0;").Append(human ? "  ! [" : "");
            _rest = new char[_restText.Length];
            _restText.CopyTo(0, _rest, _rest.Length);
            (_known, _tail, _speed, _zone, _tool) = (true, Targets.Version, speed, zone, tool);
        }
        string? described = human && action is not ActionTranslation ? ProgramText.CommentText(action.Describe()) : null;
        int need = start.Length + 8 + 3 * NumAppend.MaxChars + _rest.Length + ActionTranslation.MaxDescriptionChars + (described?.Length ?? 0) + 1;
        if (_line.Length < need)
        {
            _line = new char[need * 2];
        }
        Span<char> line = _line;
        start.CopyTo(line);
        int at = start.Length;
        line[at++] = '[';
        line[at++] = '[';
        at = NumAppend.TryWriteCoordinates(line, at, position, 1, RapidFacts.MillimetreDecimals, ", ");
        if (at < 0)
        {
            return false;
        }
        line[at++] = ']';
        _rest.CopyTo(line[at..]);
        at += _rest.Length;
        if (human)
        {
            if (action is ActionTranslation translation)
            {
                at += translation.WriteDescription(line[at..]);
            }
            else
            {
                described.AsSpan().CopyTo(line[at..]);
                at += described!.Length;
            }
            line[at++] = ']';
        }
        sink.Add(line[..at]);
        return true;
    }
}
