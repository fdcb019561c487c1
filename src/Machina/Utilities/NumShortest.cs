using System.Numerics;
using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// Fast text for the numbers users wrote (12.5, -0.125): the same characters as .NET's lossless <c>"R"</c> and 15-digit
/// <c>"G15"</c> formatting, found without the general algorithm when the number has at most 9 decimals and 15 digits. A
/// compile that warns on every move prints millions of such numbers.
/// </summary>
internal static class NumShortest
{
    /// <summary>
    /// Writes the fewest decimals that read back as exactly <paramref name="value"/> into <paramref name="destination"/> (at
    /// least <see cref="NumAppend.MaxChars"/> long) and returns the number of characters, or −1 when the value needs more
    /// than 9 decimals or 15 digits, or is below 0.0001 or from 10^14 on in size (where "R" and "G15" write E notation), and
    /// the caller must format it the general way. Zero (also −0) is "0".
    /// </summary>
    /// <remarks>Characters (<see cref="char"/>) or ASCII bytes (<see cref="byte"/>): the same digits either way.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWrite<T>(Span<T> destination, double value)
        where T : unmanaged, IBinaryInteger<T>
    {
        if (value == 0)
        {
            destination[0] = T.CreateTruncating('0');
            return 1;
        }
        double size = Math.Abs(value);
        if (!(size >= 1e-4 && size < 1e14))
        {
            return -1;
        }
        // Most numbers of programs have at most 3 decimals (millimetres): one probe at 3 decimals finds their text with one
        // division instead of one per number of decimals tried. It succeeds exactly when some count of decimals up to 3 does
        // (below 10^15 the scaled value rounds to that decimal's digits), and WriteDecimal drops the trailing zeros, so the
        // text is the one the search from 0 decimals finds; when it fails below 10^15, the search can start at 4.
        int written = TryWriteThousandths(destination, value, out double milli);
        if (written >= 0)
        {
            return written;
        }
        int first = milli < 1e15 ? 4 : 0;
        for (int decimals = first; decimals <= NumAppend.MaxDecimals; decimals++)
        {
            double scaled = NumAppend.RoundEven(size * NumAppend.Pow10[decimals]);
            if (scaled >= 1e15)
            {
                return -1;
            }
            // Both are exact doubles, so the division is correctly rounded: it is the double that reading
            // "scaled · 10^-decimals" gives. The first number of decimals for which it is the value is the shortest text.
            if (scaled / NumAppend.Pow10[decimals] == size)
            {
                return NumAppend.WriteDecimal(destination, value < 0, (long)scaled, decimals);
            }
        }
        return -1;
    }

    /// <summary>
    /// Writes <paramref name="value"/> when it reads back exactly from at most 3 decimals (<see cref="TryThousandths"/>) and returns the
    /// number of characters, the text both <see cref="WriteRoundTrip"/> and <see cref="NumAppend.WriteF"/> with 3 decimals write
    /// (−0 as 0); −1 otherwise. <paramref name="milli"/> is the size · 1000 rounded to a whole number either way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteThousandths<T>(Span<T> destination, double value, out double milli)
        where T : unmanaged, IBinaryInteger<T> =>
        TryThousandths(Math.Abs(value), out milli) ? NumAppend.WriteDecimal(destination, value < 0, (long)milli, 3) : -1;

    /// <summary>
    /// True when <paramref name="size"/> (not negative) reads back exactly from at most 3 decimals, with fewer than 10^15
    /// thousandths: <paramref name="milli"/> is then its count of thousandths (always the size · 1000 rounded to a whole number).
    /// </summary>
    internal static bool TryThousandths(double size, out double milli)
    {
        milli = NumAppend.RoundEven(size * 1e3);
        // Both are exact doubles, so the division is correctly rounded: the double that reading the decimal gives.
        return milli < 1e15 && milli / 1e3 == size;
    }

    /// <summary>Writes exactly what <c>Num.Clean(value).ToString("R", invariant)</c> writes; returns the number of characters.</summary>
    internal static int WriteRoundTrip(Span<char> destination, double value) => Write(destination, value, "R");

    /// <summary>Writes exactly what <c>Num.Clean(value).ToString("G15", invariant)</c> writes; returns the number of characters.</summary>
    /// <remarks>
    /// A value that reads back from at most 15 digits is within half a unit in the last place of that decimal, far less than
    /// half a step of the 15th digit, so G15 rounds it to the same decimal and prints the same text.
    /// </remarks>
    internal static int WriteGeneral(Span<char> destination, double value) => Write(destination, value, "G15");

    /// <summary>The shortest text when it reads back, else what .NET writes with <paramref name="fallback"/>; the number of characters.</summary>
    private static int Write(Span<char> destination, double value, string fallback)
    {
        int written = TryWrite(destination, value);
        if (written >= 0)
        {
            return written;
        }
        Num.Clean(value).TryFormat(destination, out written, fallback, Num.Inv);
        return written;
    }

    /// <summary>Appends the text of <see cref="WriteGeneral"/> (G15, −0 as 0).</summary>
    internal static System.Text.StringBuilder AppendGeneral(this System.Text.StringBuilder sb, double value)
    {
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        return sb.Append(buffer[..WriteGeneral(buffer, value)]);
    }
}
