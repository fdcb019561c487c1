using System.Globalization;

namespace Machina;

/// <summary>
/// Culture-independent number formatting for text people read (messages, warnings, logs, events) and for the wire messages that
/// print numbers as the original host did. Negative zero is always printed as 0. A program's numbers are written by
/// <see cref="NumAppend"/>, whose one policy (plain notation; NaN and infinities refused) every language shares.
/// </summary>
internal static class Num
{
    internal static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>Removes negative zero so that it never prints as "-0".</summary>
    internal static double Clean(double value) => value == 0 ? 0 : value;

    /// <summary>Lossless text: parses back to exactly the same double.</summary>
    internal static string R(double value) => Clean(value).ToString("R", Inv);

    /// <summary>Up to 15 significant digits, as the original library printed unrounded numbers (1.5 × 10.4 → 15.6).</summary>
    internal static string G(double value) => Clean(value).ToString("G15", Inv);

    /// <summary>Rounded to <paramref name="decimals"/> decimals (midpoint to even), printed in shortest form.</summary>
    internal static string F(double value, int decimals)
    {
        Span<char> buffer = stackalloc char[NumAppend.MaxChars];
        return new string(buffer[..NumAppend.WriteF(buffer, value, decimals)]);
    }

    /// <summary>Integer text.</summary>
    internal static string I(long value) => value.ToString(Inv);

    /// <summary>Throws a clear error when a number is NaN or infinite.</summary>
    internal static double Finite(double value, string name)
    {
        if (!double.IsFinite(value))
        {
            throw new ArgumentException($"{name} must be a finite number, but it was {value.ToString(Inv)}.", name);
        }
        return value;
    }
}
