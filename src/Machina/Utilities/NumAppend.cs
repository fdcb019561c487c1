using System.Text;

namespace Machina;

/// <summary>
/// Fast, allocation-free number text for compilers that write millions of values. Same digits as
/// <see cref="Num.F(double, int)"/> (midpoint-to-even rounding, −0 as 0), but always in plain decimal notation
/// (0.00001, never 1E-05), which every robot language reads.
/// </summary>
internal static class NumAppend
{
    private static readonly double[] Pow10 = [1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];
    private static readonly long[] Pow10L = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000, 100_000_000, 1_000_000_000];

    /// <summary>Appends <paramref name="value"/> rounded to <paramref name="decimals"/> (0–9) decimals, trailing zeros removed.</summary>
    internal static StringBuilder AppendFixed(this StringBuilder sb, double value, int decimals)
    {
        Span<char> buffer = stackalloc char[MaxChars];
        int written = TryWriteScaled(buffer, value, decimals);
        if (written < 0)
        {
            return sb.Append(Num.Inv, $"{Num.Clean(Math.Round(value, decimals)):G15}");
        }
        return sb.Append(buffer[..written]);
    }

    /// <summary>Characters enough for any number this class or <see cref="Num.F(double, int)"/> writes.</summary>
    internal const int MaxChars = 32;

    /// <summary>
    /// Writes <paramref name="value"/> rounded to <paramref name="decimals"/> (0–9) decimals into <paramref name="destination"/>
    /// (at least <see cref="MaxChars"/> long) in plain decimal notation and returns the number of characters, or −1 when the
    /// rounded value has more than 15 significant digits, or is not finite, and the caller must format it another way.
    /// </summary>
    internal static int TryWriteScaled(Span<char> destination, double value, int decimals)
    {
        // Math.Round(value, decimals) scales, rounds to even and scales back; doing the first two steps here gives the
        // same digits as an integer, which prints exactly while it has at most 15 significant digits.
        double scaled = Math.Round(value * Pow10[decimals]);
        if (!(Math.Abs(scaled) < 1e15))
        {
            return -1;
        }
        return WriteDecimal(destination, scaled < 0, (long)Math.Abs(scaled), decimals);
    }

    /// <summary>
    /// Writes <paramref name="mantissa"/> · 10^−<paramref name="decimals"/> (0–9 decimals; the mantissa below 10^18) in plain
    /// decimal notation, trailing zeros of the fraction removed, '-' first when <paramref name="negative"/> and the number is not
    /// 0; returns the number of characters. Digits are written by hand: the general integer formatter took about 5 % of a RAPID compile.
    /// </summary>
    internal static int WriteDecimal(Span<char> destination, bool negative, long mantissa, int decimals)
    {
        int at = 0;
        if (negative && mantissa != 0)
        {
            destination[at++] = '-';
        }
        long whole = Math.DivRem(mantissa, Pow10L[decimals], out long fraction);
        at += WriteDigits(destination[at..], whole, 1);
        if (fraction == 0)
        {
            return at;
        }
        int digits = decimals;
        while (fraction % 10 == 0)
        {
            fraction /= 10;
            digits--;
        }
        destination[at++] = '.';
        return at + WriteDigits(destination[at..], fraction, digits);
    }

    /// <summary>Writes a non-negative number with at least <paramref name="minDigits"/> digits (leading zeros); returns their count.</summary>
    private static int WriteDigits(Span<char> destination, long value, int minDigits)
    {
        int count = 1;
        for (long rest = value / 10; rest != 0; rest /= 10)
        {
            count++;
        }
        count = Math.Max(count, minDigits);
        for (int i = count - 1; i >= 0; i--)
        {
            long next = value / 10;
            destination[i] = (char)('0' + (int)(value - next * 10));
            value = next;
        }
        return count;
    }

    /// <summary>
    /// Writes exactly the text of <see cref="Num.F(double, int)"/> (which switches to E notation below 0.0001) into
    /// <paramref name="destination"/> (at least <see cref="MaxChars"/> long) and returns the number of characters.
    /// </summary>
    internal static int WriteF(Span<char> destination, double value, int decimals)
    {
        if ((uint)decimals < (uint)Pow10.Length)
        {
            // G15 writes fixed notation down to 0.0001 and E notation below it (1E-05): only the general path writes that.
            double scaled = Math.Abs(Math.Round(value * Pow10[decimals]));
            if (decimals <= 4 || scaled == 0 || scaled >= Pow10[decimals - 4])
            {
                int written = TryWriteScaled(destination, value, decimals);
                if (written >= 0)
                {
                    return written;
                }
            }
        }
        Num.Clean(Math.Round(value, decimals)).TryFormat(destination, out int general, "G15", Num.Inv);
        return general;
    }
}
