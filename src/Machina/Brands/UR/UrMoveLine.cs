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

    // A description that is not written as bytes, as characters (TryWriteDescription), narrowed into the line.
    private readonly char[] _description = new char[RobotAction.MaxWrittenDescriptionChars];

    /// <summary>
    /// Writes the line of <paramref name="action"/> (a move, a turn, any motion to a pose) into <paramref name="sink"/>, as ASCII
    /// bytes in the sink's own room (<see cref="LineSink.BeginAscii"/>); false (nothing written) when a coordinate is too large for
    /// the fast digits, or the comment <paramref name="human"/> asks for is not one of digits and fixed words in ASCII
    /// (<see cref="RobotAction.TryWriteDescription"/>), and the caller writes the line the general way.
    /// </summary>
    /// <remarks>
    /// The description is written as bytes in its place in the line: a move's from the digits it shares with its instruction
    /// (<see cref="TranslationDigits"/>), a turn's by <see cref="RobotAction.TryWriteDescriptionAscii"/>; characters narrowed
    /// only where neither writes it.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal bool TryWrite(LineSink sink, RobotAction action, RobotCursor cursor, bool joint, bool human)
    {
        ReadOnlySpan<byte> orientation = repeated.OrientationAscii(cursor.Rotation!.Value);
        ReadOnlySpan<byte> parameters = repeated.ParametersAscii(cursor.Acceleration, cursor.Speed, cursor.Precision, joint);
        Span<byte> line = sink.BeginAscii(MostChars + orientation.Length + parameters.Length);
        ReadOnlySpan<byte> start = joint ? "  movej(p["u8 : "  movep(p["u8;
        start.CopyTo(line);
        int at = NumAppend.TryWriteCoordinatesAscii(line, start.Length, cursor.Position!.Value, UrScriptText.Mm, 6, ","u8);
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
            int written = action is ActionTranslation move ? digits.TryWriteDescriptionAscii(move, line[(at + Opening.Length)..]) : -1;
            if (written >= 0)
            {
                Opening.CopyTo(line[at..]);
                at += Opening.Length + written;
                line[at++] = (byte)']';
            }
            else if ((at = AsciiNarrow.TryWriteDescription(line, at, Opening, action, _description)) < 0)
            {
                return false;
            }
        }
        sink.EndAscii(at);
        return true;
    }

    /// <summary>What comes before a line's description.</summary>
    private static ReadOnlySpan<byte> Opening => "  # ["u8;
}
