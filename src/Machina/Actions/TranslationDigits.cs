using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Machina;

/// <summary>
/// The three numbers of the last move asked about, as ASCII bytes: a compile that warns on a move quotes it twice, its
/// instruction in the warning (<see cref="ActionTranslation.WriteInstruction"/>, shortest round-trip numbers) and its
/// description in the line's comment (<see cref="ActionTranslation.WriteDescription"/>, 3 decimals). When each number reads
/// back exactly from at most 3 decimals the two show the same digits, which are then written once for both, as bytes into
/// lines written as bytes (<see cref="LineSink.BeginAscii"/>).
/// </summary>
internal sealed class TranslationDigits
{
    // The three numbers as the description shows them, "x, y, z", with room after them for a copy of 16 bytes at a time.
    private readonly byte[] _spaced = new byte[3 * NumAppend.MaxChars + 4 + 32];
    private int _endX, _endY, _endZ;
    private ActionTranslation? _move;
    private bool _shared;

    /// <summary>
    /// Writes the bytes of <see cref="ActionTranslation.WriteInstruction"/>'s text for <paramref name="move"/> (room for
    /// <see cref="ActionTranslation.MaxInstructionChars"/> + 16); returns their count, or −1 when its numbers are not the shared
    /// digits and the caller writes it the general way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal int TryWriteInstructionAscii(ActionTranslation move, Span<byte> destination)
    {
        if (!Prepare(move))
        {
            return -1;
        }
        int at;
        if (move.Relative)
        {
            "Move("u8.CopyTo(destination);
            at = 5;
        }
        else
        {
            "MoveTo("u8.CopyTo(destination);
            at = 7;
        }
        ReadOnlySpan<byte> spaced = _spaced;
        at = CopyShort(destination, at, spaced, 0, _endX);
        destination[at++] = (byte)',';
        at = CopyShort(destination, at, spaced, _endX + 2, _endY - _endX - 2);
        destination[at++] = (byte)',';
        at = CopyShort(destination, at, spaced, _endY + 2, _endZ - _endY - 2);
        destination[at] = (byte)')';
        destination[at + 1] = (byte)';';
        return at + 2;
    }

    /// <summary>
    /// Writes the bytes of <see cref="ActionTranslation.WriteDescription"/>'s text for <paramref name="move"/> (room for
    /// <see cref="ActionTranslation.MaxDescriptionChars"/> + 32); returns their count, or −1 as <see cref="TryWriteInstructionAscii"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal int TryWriteDescriptionAscii(ActionTranslation move, Span<byte> destination)
    {
        if (!Prepare(move))
        {
            return -1;
        }
        int at;
        if (move.Relative)
        {
            "Move ["u8.CopyTo(destination);
            at = 6;
        }
        else
        {
            "Move to ["u8.CopyTo(destination);
            at = 9;
        }
        ReadOnlySpan<byte> spaced = _spaced;
        if (_endZ <= 32 && destination.Length - at >= 32)
        {
            // The three numbers in two copies of 16 bytes (what follows them in the line is written over next).
            Vector128.Create(spaced[..16]).CopyTo(destination.Slice(at, 16));
            Vector128.Create(spaced.Slice(16, 16)).CopyTo(destination.Slice(at + 16, 16));
            at += _endZ;
        }
        else
        {
            spaced[.._endZ].CopyTo(destination[at..]);
            at += _endZ;
        }
        "] mm"u8.CopyTo(destination[at..]);
        return at + 4;
    }

    /// <summary>
    /// Copies <paramref name="length"/> bytes of <paramref name="source"/> from <paramref name="start"/> to <paramref name="at"/>:
    /// a number of up to 16 bytes as one copy of 16 (a call to the general copy cost more than the bytes themselves); returns
    /// the position after them.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int CopyShort(Span<byte> destination, int at, ReadOnlySpan<byte> source, int start, int length)
    {
        if (length <= 16 && destination.Length - at >= 16)
        {
            Vector128.Create(source.Slice(start, 16)).CopyTo(destination.Slice(at, 16));
        }
        else
        {
            source.Slice(start, length).CopyTo(destination[at..]);
        }
        return at + length;
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
        Span<byte> spaced = _spaced;
        _shared = TryMilli(spaced, 0, v.X, out _endX) && TryMilli(spaced, DescriptionAscii.Separator(spaced, _endX), v.Y, out _endY)
                  && TryMilli(spaced, DescriptionAscii.Separator(spaced, _endY), v.Z, out _endZ);
        return _shared;
    }

    /// <summary>Writes <paramref name="value"/> when both texts show it alike (<see cref="NumShortest.TryWriteThousandths"/>); false otherwise.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static bool TryMilli(Span<byte> digits, int at, double value, out int end)
    {
        int written = NumShortest.TryWriteThousandths(digits[at..], value, out _);
        end = at + Math.Max(written, 0);
        return written >= 0;
    }
}
