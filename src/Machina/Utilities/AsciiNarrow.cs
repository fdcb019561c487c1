using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace Machina;

/// <summary>
/// Narrows a short text (a move's description, an instruction, a kept number's text: tens of characters) into ASCII bytes in
/// one pass, sixteen characters a step. <see cref="System.Text.Ascii.FromUtf16"/> pays a set-up per call that outweighs such
/// texts, and in the JIT tool its precompiled code is slower still (it was 7 % of a KRL compile there).
/// </summary>
internal static class AsciiNarrow
{
    /// <summary>
    /// Writes the bytes of <paramref name="text"/> at the start of <paramref name="destination"/> (at least as long) and returns
    /// their count, or −1 when a character is not ASCII (the bytes written then mean nothing).
    /// </summary>
    internal static int TryWrite(ReadOnlySpan<char> text, Span<byte> destination)
    {
        ReadOnlySpan<ushort> units = MemoryMarshal.Cast<char, ushort>(text);
        destination = destination[..units.Length];
        int i = 0;
        if (Vector128.IsHardwareAccelerated)
        {
            Vector128<ushort> notAscii = Vector128.Create((ushort)0xFF80);
            for (; i + 16 <= units.Length; i += 16)
            {
                Vector128<ushort> low = Vector128.Create(units.Slice(i, 8)), high = Vector128.Create(units.Slice(i + 8, 8));
                if (((low | high) & notAscii) != Vector128<ushort>.Zero)
                {
                    return -1;
                }
                Vector128.Narrow(low, high).CopyTo(destination.Slice(i, 16));
            }
        }
        int bits = 0;
        for (; i < units.Length; i++)
        {
            int unit = units[i];
            bits |= unit;
            destination[i] = (byte)unit;
        }
        return bits < 0x80 ? units.Length : -1;
    }

    /// <summary>
    /// Writes <paramref name="opening"/>, the description of <paramref name="action"/> and <c>]</c> at <paramref name="at"/> (a
    /// line's comment such as <c>  ; [Move [1, 2, 3] mm]</c>, room for <see cref="RobotAction.MaxWrittenDescriptionChars"/> + 1
    /// after the opening): as bytes where the action writes them (<see cref="RobotAction.TryWriteDescriptionAscii"/>), else its
    /// characters (<see cref="RobotAction.TryWriteDescription"/>, written into <paramref name="scratch"/>) narrowed; returns the
    /// position after them, or −1 when the action writes neither or its text is not ASCII.
    /// </summary>
    internal static int TryWriteDescription(Span<byte> line, int at, ReadOnlySpan<byte> opening, RobotAction action, Span<char> scratch)
    {
        opening.CopyTo(line[at..]);
        at += opening.Length;
        int written = action.TryWriteDescriptionAscii(line[at..]);
        if (written < 0)
        {
            int length = action.TryWriteDescription(scratch);
            if (length < 0 || (written = TryWrite(scratch[..length], line[at..])) < 0)
            {
                return -1;
            }
        }
        at += written;
        line[at] = (byte)']';
        return at + 1;
    }
}
