using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes a whole <c>MoveL</c>/<c>MoveJ</c> line with an inline robtarget into one reused array, as <see cref="RapidWriter"/>
/// writes it through a builder: the position's three numbers, the orientation's quaternion (kept while it stays the same), then
/// the text after it (configuration, external axes, speed, zone, tool and the comment's start) kept while all of it stays the
/// same, then the move's description. A toolpath changes only its position from move to move, so one copy replaces a dozen
/// appends to a builder.
/// </summary>
internal sealed class RapidMoveLine
{
    /// <summary>The inline targets' kept text, shared with the writer's other lines (arcs).</summary>
    internal RapidTargetText Targets { get; } = new();

    private readonly StringBuilder _afterText = new(192);
    private byte[] _after = new byte[192];
    private int _afterLength;
    private bool _known, _human, _afterIsAscii;
    private int _restVersion;
    private string? _speed, _zone, _tool, _start;
    private byte[] _startAscii = new byte[32];
    private int _startLength = -1;

    // A description that is not written as bytes, as characters (TryWriteDescription), narrowed into the line.
    private readonly char[] _description = new char[RobotAction.MaxWrittenDescriptionChars];

    /// <summary>
    /// Writes <paramref name="start"/> (indent and instruction) and the inline target (its orientation, configuration and axes
    /// through <see cref="Targets"/>), speed, zone, tool and, with <paramref name="human"/>, the action's comment into
    /// <paramref name="sink"/> as one line of ASCII bytes in the sink's own room (<see cref="LineSink.BeginAscii"/>: the line
    /// is written once, in place, not narrowed from characters); false (nothing written) when a coordinate is too large for the
    /// fast digits, or a text of the line is not ASCII or its description not one of digits and fixed words, and the caller
    /// writes the line the general way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal bool TryWrite(LineSink sink, string start, Vector position, Rotation rotation, ExternalAxes? axes, double? armAngle,
                           AbbConfiguration? conf, string speed, string zone, string tool, RobotAction action, bool human)
    {
        ReadOnlySpan<byte> quaternion = Targets.QuaternionAscii(rotation);
        StringBuilder rest = Targets.Rest(axes, armAngle, conf);
        if (!_known || Targets.RestVersion != _restVersion || !ReferenceEquals(speed, _speed) || !ReferenceEquals(zone, _zone)
            || !ReferenceEquals(tool, _tool) || human != _human)
        {
            _afterText.Clear().Append(rest).Append(", ").Append(speed).Append(", ").Append(zone).Append(", ").Append(tool)
                      .Append("\\WObj:=WObj0;").Append(human ? "  ! [" : "");
            _afterIsAscii = Keep(_afterText, ref _after, out _afterLength);
            (_known, _restVersion, _speed, _zone, _tool, _human) = (true, Targets.RestVersion, speed, zone, tool, human);
        }
        if (!ReferenceEquals(start, _start))
        {
            if (_startAscii.Length < start.Length)
            {
                _startAscii = new byte[start.Length];
            }
            _startLength = AsciiNarrow.TryWrite(start, _startAscii);
            _start = start;
        }
        if (!_afterIsAscii || _startLength < 0)
        {
            return false;
        }
        Span<byte> line = sink.BeginAscii(_startLength + 8 + 3 * NumAppend.MaxChars + quaternion.Length + _afterLength + RobotAction.MaxWrittenDescriptionChars + 1);
        _startAscii.AsSpan(0, _startLength).CopyTo(line);
        int at = _startLength;
        line[at++] = (byte)'[';
        line[at++] = (byte)'[';
        at = NumAppend.TryWriteCoordinatesAscii(line, at, position, 1, RapidFacts.MillimetreDecimals, ", "u8);
        if (at < 0)
        {
            return false;
        }
        line[at++] = (byte)']';
        line[at++] = (byte)',';
        line[at++] = (byte)' ';
        quaternion.CopyTo(line[at..]);
        at += quaternion.Length;
        _after.AsSpan(0, _afterLength).CopyTo(line[at..]);
        at += _afterLength;
        // The description is written in its place in the line (its opening is the kept text's end).
        if (human && (at = Describe(line, at, action)) < 0)
        {
            return false;
        }
        sink.EndAscii(at);
        return true;
    }

    /// <summary>
    /// Writes the action's description and <c>]</c> at <paramref name="at"/>: as bytes where it writes them, else its text made
    /// comment-safe (<see cref="ProgramText.CommentText"/>) when that is ASCII and fits the room; −1 otherwise.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Describe(Span<byte> line, int at, RobotAction action)
    {
        int after = AsciiNarrow.TryWriteDescription(line, at, default, action, _description);
        if (after >= 0)
        {
            return after;
        }
        string described = ProgramText.CommentText(action.Describe());
        int written;
        if (described.Length > RobotAction.MaxWrittenDescriptionChars || (written = AsciiNarrow.TryWrite(described, line[at..])) < 0)
        {
            return -1;
        }
        at += written;
        line[at] = (byte)']';
        return at + 1;
    }

    /// <summary>
    /// Keeps the ASCII bytes of <paramref name="text"/> in <paramref name="kept"/> (grown when too short); false when the text is
    /// not all ASCII (a name outside it: the line is then written the general way, whose sink writes what the file holds).
    /// </summary>
    private static bool Keep(StringBuilder text, ref byte[] kept, out int length)
    {
        length = text.Length;
        if (kept.Length < length)
        {
            kept = new byte[length * 2];
        }
        Span<char> chars = length <= 256 ? stackalloc char[length] : new char[length];
        text.CopyTo(0, chars, length);
        return AsciiNarrow.TryWrite(chars, kept) >= 0;
    }
}
