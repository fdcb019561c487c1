using System.Text;

namespace Machina;

/// <summary>
/// Fast fixed-point number text for program compilers that write millions of numbers: the same text as <c>Num.F</c>
/// (midpoint-to-even rounding, trailing zeros dropped, never "-0"), but never in exponent form and without allocating.
/// </summary>
internal static class FixedPoint
{
    private static readonly long[] Powers = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000, 100_000_000];

    /// <summary>Appends <paramref name="value"/> rounded to <paramref name="decimals"/> (0 to 8) decimals.</summary>
    internal static StringBuilder Append(StringBuilder sb, double value, int decimals)
    {
        long power = Powers[decimals];
        double scaled = Math.Round(value * power);
        if (!(Math.Abs(scaled) < 1e15))
        {
            // Huge or not finite: rare enough for the general formatter.
            return sb.Append(Num.Clean(Math.Round(value, decimals)).ToString("0." + new string('#', Math.Max(1, decimals)), Num.Inv));
        }
        long n = (long)scaled;
        if (n < 0)
        {
            sb.Append('-');
            n = -n;
        }
        long whole = Math.DivRem(n, power, out long fraction);
        AppendDigits(sb, whole, 0);
        if (fraction != 0)
        {
            int digits = decimals;
            while (fraction % 10 == 0)
            {
                fraction /= 10;
                digits--;
            }
            sb.Append('.');
            AppendDigits(sb, fraction, digits);
        }
        return sb;
    }

    /// <summary>The text of <paramref name="value"/> rounded to <paramref name="decimals"/> decimals.</summary>
    internal static string Format(double value, int decimals) => Append(new StringBuilder(24), value, decimals).ToString();

    // Writes a non-negative number with at least minDigits digits (leading zeros), ASCII only, whatever the culture.
    private static void AppendDigits(StringBuilder sb, long value, int minDigits)
    {
        Span<char> buffer = stackalloc char[20];
        int i = buffer.Length;
        do
        {
            buffer[--i] = (char)('0' + (int)(value % 10));
            value /= 10;
        }
        while (value != 0);
        while (buffer.Length - i < minDigits)
        {
            buffer[--i] = '0';
        }
        sb.Append(buffer[i..]);
    }
}
