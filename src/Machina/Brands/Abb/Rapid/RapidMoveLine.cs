using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes a whole <c>MoveL</c>/<c>MoveJ</c> line with an inline robtarget into one reused array, as <see cref="RapidWriter"/>
/// writes it through a builder: the position's three numbers, the orientation's quaternion (kept while it stays the same), then
/// the text after it (configuration, external axes, speed, zone, tool and the comment's start) kept while all of it stays the
/// same, then the move's description. A toolpath changes only its position from move to move, so one copy replaces a dozen
/// appends to a builder. The sink is told where the kept text (orientation to the comment's start) is in the line: a program in
/// memory stores it once for the moves that repeat it (<see cref="LineSink.Add(ReadOnlySpan{char}, int, int)"/>).
/// </summary>
internal sealed class RapidMoveLine
{
    /// <summary>The inline targets' kept text, shared with the writer's other lines (arcs).</summary>
    internal RapidTargetText Targets { get; } = new();

    private readonly StringBuilder _afterText = new(192);
    private char[] _line = new char[256];
    private char[] _after = new char[192];
    private int _afterLength;
    private bool _known, _human;
    private int _restVersion;
    private string? _speed, _zone, _tool;

    /// <summary>
    /// Writes <paramref name="start"/> (indent and instruction) and the inline target (its orientation, configuration and axes
    /// through <see cref="Targets"/>), speed, zone, tool and, with <paramref name="human"/>, the action's comment into
    /// <paramref name="sink"/> as one line; false (nothing written) when a coordinate is too large for the fast digits, and the
    /// caller writes the line the general way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal bool TryWrite(LineSink sink, string start, Vector position, Rotation rotation, ExternalAxes? axes, double? armAngle,
                           AbbConfiguration? conf, string speed, string zone, string tool, RobotAction action, bool human)
    {
        ReadOnlySpan<char> quaternion = Targets.Quaternion(rotation);
        StringBuilder rest = Targets.Rest(axes, armAngle, conf);
        if (!_known || Targets.RestVersion != _restVersion || !ReferenceEquals(speed, _speed) || !ReferenceEquals(zone, _zone)
            || !ReferenceEquals(tool, _tool) || human != _human)
        {
            _afterText.Clear().Append(rest).Append(", ").Append(speed).Append(", ").Append(zone).Append(", ").Append(tool)
                      .Append("\\WObj:=WObj0;").Append(human ? "  ! [" : "");
            if (_after.Length < _afterText.Length)
            {
                _after = new char[_afterText.Length * 2];
            }
            _afterLength = _afterText.Length;
            _afterText.CopyTo(0, _after, _afterLength);
            (_known, _restVersion, _speed, _zone, _tool, _human) = (true, Targets.RestVersion, speed, zone, tool, human);
        }
        int need = start.Length + 8 + 3 * NumAppend.MaxChars + quaternion.Length + _afterLength + RobotAction.MaxWrittenDescriptionChars + 1;
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
        line[at++] = ',';
        line[at++] = ' ';
        int kept = at; // the orientation and the text after it: the same from move to move in a toolpath
        quaternion.CopyTo(line[at..]);
        at += quaternion.Length;
        _after.AsSpan(0, _afterLength).CopyTo(line[at..]);
        at += _afterLength;
        int keptLength = at - kept;
        if (human)
        {
            // The description is written in its place in the line: no buffer of its own to clear and copy from.
            int ownLength = action.TryWriteDescription(line[at..]);
            if (ownLength >= 0)
            {
                at += ownLength;
            }
            else
            {
                string described = ProgramText.CommentText(action.Describe());
                if (line.Length < at + described.Length + 1)
                {
                    char[] longer = new char[(at + described.Length + 1) * 2];
                    line[..at].CopyTo(longer);
                    _line = longer;
                    line = longer;
                }
                described.CopyTo(line[at..]);
                at += described.Length;
            }
            line[at++] = ']';
        }
        sink.Add(line[..at], kept, keptLength);
        return true;
    }
}
