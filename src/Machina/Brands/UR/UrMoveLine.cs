using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// Writes a whole <c>movep</c>/<c>movej</c> line of a move or a turn with an inline pose into one reused array, as
/// <see cref="UrScriptWriter"/> writes it through a builder: the position's three numbers, the kept orientation and parameters
/// (<see cref="UrRepeatedText"/>), then the action's description (a move's through <see cref="TranslationDigits"/>, a turn's
/// through <see cref="RobotAction.TryWriteDescription"/>). A toolpath changes only its position from move to move, so a few
/// copies replace a dozen appends to a builder.
/// </summary>
internal sealed class UrMoveLine(UrRepeatedText repeated, TranslationDigits digits)
{
    private const int MostChars = 16 + 3 * (NumAppend.MaxChars + 1) + RobotAction.MaxWrittenDescriptionChars + 8;

    private char[] _line = new char[256];

    /// <summary>
    /// Writes the line of <paramref name="action"/> (a move, a turn, any motion to a pose) into <paramref name="sink"/>; false
    /// (nothing written) when a coordinate is too large for the fast digits, or the comment <paramref name="human"/> asks for is
    /// not one of digits and fixed words (<see cref="RobotAction.TryWriteDescription"/>), and the caller writes the line the general way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal bool TryWrite(LineSink sink, RobotAction action, RobotCursor cursor, bool joint, bool human)
    {
        var move = action as ActionTranslation;
        Span<char> turn = stackalloc char[RobotAction.MaxWrittenDescriptionChars];
        int turnLength = human && move is null ? action.TryWriteDescription(turn) : 0;
        if (turnLength < 0)
        {
            return false;
        }
        ReadOnlySpan<char> orientation = repeated.Orientation(cursor.Rotation!.Value);
        ReadOnlySpan<char> parameters = repeated.Parameters(cursor.Acceleration, cursor.Speed, cursor.Precision, joint);
        int need = MostChars + orientation.Length + parameters.Length;
        if (_line.Length < need)
        {
            _line = new char[need * 2];
        }
        Span<char> line = _line;
        ReadOnlySpan<char> start = joint ? "  movej(p[" : "  movep(p[";
        start.CopyTo(line);
        int at = start.Length;
        at = NumAppend.TryWriteCoordinates(line, at, cursor.Position!.Value, UrScriptText.Mm, 6, ",");
        if (at < 0)
        {
            return false;
        }
        orientation.CopyTo(line[at..]);
        at += orientation.Length;
        parameters.CopyTo(line[at..]);
        at += parameters.Length;
        if (human)
        {
            "  # [".CopyTo(line[at..]);
            at += 5;
            if (move is not null)
            {
                at += digits.WriteDescription(move, line[at..]);
            }
            else
            {
                turn[..turnLength].CopyTo(line[at..]);
                at += turnLength;
            }
            line[at++] = ']';
        }
        sink.Add(line[..at]);
        return true;
    }
}
