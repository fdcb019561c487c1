using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// The pieces of a move's or a turn's description (<see cref="RobotAction.TryWriteDescriptionAscii"/>) as ASCII bytes, for
/// compilers that write their lines as bytes (<see cref="LineSink.BeginAscii"/>): the same text as the characters, without
/// narrowing them per line.
/// </summary>
internal static class DescriptionAscii
{
    /// <summary>
    /// Writes <c>[x, y, z]</c> (3 decimals) as <see cref="Vector.WriteText"/> writes it with <c>", "</c>; returns the count of
    /// bytes, or −1 when a number takes .NET's general text there (E notation, huge values).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteVector(Span<byte> destination, Vector vector)
    {
        destination[0] = (byte)'[';
        int at = 1, written;
        if ((written = NumAppend.TryWriteFAscii(destination[at..], vector.X, 3)) < 0)
        {
            return -1;
        }
        at = Separator(destination, at + written);
        if ((written = NumAppend.TryWriteFAscii(destination[at..], vector.Y, 3)) < 0)
        {
            return -1;
        }
        at = Separator(destination, at + written);
        if ((written = NumAppend.TryWriteFAscii(destination[at..], vector.Z, 3)) < 0)
        {
            return -1;
        }
        at += written;
        destination[at++] = (byte)']';
        return at;
    }

    /// <summary>Writes <c>", "</c> at <paramref name="at"/>; returns the position after it.</summary>
    internal static int Separator(Span<byte> destination, int at)
    {
        destination[at] = (byte)',';
        destination[at + 1] = (byte)' ';
        return at + 2;
    }
}
