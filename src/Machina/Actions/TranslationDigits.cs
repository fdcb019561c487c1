using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// The three numbers of the last move asked about, as text: a compile that warns on a move quotes it twice, its instruction in
/// the warning (<see cref="ActionTranslation.WriteInstruction"/>, shortest round-trip numbers) and its description in the line's
/// comment (<see cref="ActionTranslation.WriteDescription"/>, 3 decimals). When each number reads back exactly from at most 3
/// decimals the two show the same digits, which are then written once for both.
/// </summary>
internal sealed class TranslationDigits
{
    private readonly char[] _digits = new char[3 * NumAppend.MaxChars];
    private int _endX, _endY, _endZ;
    private ActionTranslation? _move;
    private bool _shared;

    /// <summary>Writes the text of <see cref="ActionTranslation.WriteInstruction"/> for <paramref name="move"/>; returns its length.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal int WriteInstruction(ActionTranslation move, Span<char> destination) =>
        Prepare(move) ? Quote(destination, move.Relative ? "Move(" : "MoveTo(", ',', ");") : move.WriteInstruction(destination);

    /// <summary>Writes the text of <see cref="ActionTranslation.WriteDescription"/> for <paramref name="move"/>; returns its length.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal int WriteDescription(ActionTranslation move, Span<char> destination) =>
        Prepare(move) ? Quote(destination, move.Relative ? "Move [" : "Move to [", ' ', "] mm") : move.WriteDescription(destination);

    /// <summary>Writes <paramref name="start"/>, the kept numbers and <paramref name="end"/>; returns the length.</summary>
    private int Quote(Span<char> destination, ReadOnlySpan<char> start, char style, ReadOnlySpan<char> end)
    {
        start.CopyTo(destination);
        int at = Numbers(destination, start.Length, style);
        end.CopyTo(destination[at..]);
        return at + end.Length;
    }

    /// <summary>Copies the three numbers at <paramref name="at"/>, separated by ',' (instruction) or ", " (description).</summary>
    private int Numbers(Span<char> destination, int at, char style)
    {
        ReadOnlySpan<char> digits = _digits;
        digits[.._endX].CopyTo(destination[at..]);
        at += _endX;
        at = Separator(destination, at, style);
        digits[_endX.._endY].CopyTo(destination[at..]);
        at += _endY - _endX;
        at = Separator(destination, at, style);
        digits[_endY.._endZ].CopyTo(destination[at..]);
        return at + _endZ - _endY;
    }

    private static int Separator(Span<char> destination, int at, char style)
    {
        destination[at++] = ',';
        if (style == ' ')
        {
            destination[at++] = ' ';
        }
        return at;
    }

    /// <summary>Makes the digits of <paramref name="move"/> current; false when its two texts differ and each must be written its own way.</summary>
    private bool Prepare(ActionTranslation move)
    {
        if (ReferenceEquals(move, _move))
        {
            return _shared;
        }
        _move = move;
        Vector v = move.Translation;
        Span<char> digits = _digits;
        _shared = TryMilli(digits, 0, v.X, out _endX) && TryMilli(digits, _endX, v.Y, out _endY) && TryMilli(digits, _endY, v.Z, out _endZ);
        return _shared;
    }

    /// <summary>Writes <paramref name="value"/> when both texts show it alike (<see cref="NumShortest.TryWriteThousandths"/>); false otherwise.</summary>
    private static bool TryMilli(Span<char> digits, int at, double value, out int end)
    {
        int written = NumShortest.TryWriteThousandths(digits[at..], value, out _);
        end = at + Math.Max(written, 0);
        return written >= 0;
    }
}
