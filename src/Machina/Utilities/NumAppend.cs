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
        // Math.Round(value, decimals) scales, rounds to even and scales back; doing the first two steps here gives the
        // same digits as an integer, which prints exactly while it has at most 15 significant digits.
        double scaled = Math.Round(value * Pow10[decimals]);
        if (!(Math.Abs(scaled) < 1e15))
        {
            return sb.Append(Num.Inv, $"{Num.Clean(Math.Round(value, decimals)):G15}");
        }
        long m = (long)scaled;
        if (m < 0)
        {
            sb.Append('-');
            m = -m;
        }
        long unit = Pow10L[decimals];
        long whole = Math.DivRem(m, unit, out long fraction);
        sb.Append(Num.Inv, $"{whole}");
        if (fraction == 0)
        {
            return sb;
        }
        int digits = decimals;
        while (fraction % 10 == 0)
        {
            fraction /= 10;
            digits--;
        }
        sb.Append('.');
        for (long p = Pow10L[digits - 1]; p > fraction && p > 1; p /= 10)
        {
            sb.Append('0');
        }
        return sb.Append(Num.Inv, $"{fraction}");
    }
}
