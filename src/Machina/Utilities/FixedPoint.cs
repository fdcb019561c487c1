using System.Text;

namespace Machina;

/// <summary>
/// Fast fixed-point number text for program compilers that write millions of numbers: the same text as <c>Num.F</c>
/// (midpoint-to-even rounding, trailing zeros dropped, never "-0"), but never in exponent form and without allocating.
/// </summary>
internal static class FixedPoint
{
    /// <summary>Appends <paramref name="value"/> rounded to <paramref name="decimals"/> (0 to 8) decimals.</summary>
    /// <remarks>The digits are those of <see cref="NumAppend.TryWriteScaled"/>, written into the builder in one piece.</remarks>
    internal static StringBuilder Append(StringBuilder sb, double value, int decimals)
    {
        if (!NumAppend.TryScale(value, decimals, out double scaled))
        {
            // Huge or not finite: rare enough for the general formatter.
            return sb.Append(Num.Clean(Math.Round(value, decimals)).ToString("0." + new string('#', Math.Max(1, decimals)), Num.Inv));
        }
        return sb.Append(Num.Inv, $"{new ScaledDecimal(scaled, decimals)}");
    }

    /// <summary>The text of <paramref name="value"/> rounded to <paramref name="decimals"/> decimals.</summary>
    internal static string Format(double value, int decimals) => Append(new StringBuilder(24), value, decimals).ToString();
}
