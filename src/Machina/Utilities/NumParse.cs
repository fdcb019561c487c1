using System.Globalization;
using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// Reads numbers as users write them in instruction text (12.5, -0.125, 400) without the general parser, to exactly the same
/// double: a compile of a million moves reads three million of them.
/// </summary>
internal static class NumParse
{
    /// <summary>
    /// Reads <paramref name="text"/> as <c>double.TryParse(text, NumberStyles.Float, invariant)</c> does; returns false where
    /// that returns false.
    /// </summary>
    internal static bool TryParse(ReadOnlySpan<char> text, out double value)
    {
        if (TryParseShort(text, out value))
        {
            return true;
        }
        return double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value);
    }

    /// <summary>
    /// The plain form only: an optional sign, digits with at most one decimal point, at most 15 digits in all. The digits make
    /// an integer below 2^53 and the decimals a power of ten that a double holds exactly, so their quotient, correctly rounded
    /// by the processor, is the double nearest to the decimal: what the general parser returns. Anything else returns false.
    /// </summary>
    internal static bool TryParseShort(ReadOnlySpan<char> text, out double value)
    {
        if (ReadShort(text, out value) == text.Length)
        {
            return true;
        }
        value = 0;
        return false;
    }

    /// <summary>
    /// Reads the plain form of <see cref="TryParseShort"/> from the start of <paramref name="text"/> up to the first character
    /// that cannot continue it; returns how many characters that is, or −1 when they hold no digit or more than 15.
    /// </summary>
    internal static int ReadShort(ReadOnlySpan<char> text, out double value) => ReadShortAt(text, 0, out value);

    /// <summary>
    /// Reads the plain form of <see cref="TryParseShort"/> from <paramref name="at"/> in <paramref name="text"/> up to the
    /// first character that cannot continue it; returns the position after it, or −1 when it holds no digit or more than 15.
    /// Inlined into the parser's loop over a statement's numbers (most arguments of a toolpath), where a call per number and
    /// a span cut per number were a tenth of a compile's parsing.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static int ReadShortAt(ReadOnlySpan<char> text, int at, out double value)
    {
        value = 0;
        int i = at;
        bool negative = false;
        if ((uint)i < (uint)text.Length && (text[i] == '-' || text[i] == '+'))
        {
            negative = text[i] == '-';
            i++;
        }
        // The whole part, then the fraction, each in its own loop; the count of digits is checked once at the end (a longer
        // number only runs on to its end before it is refused).
        long mantissa = 0;
        int start = i;
        uint digit;
        while ((uint)i < (uint)text.Length && (digit = (uint)(text[i] - '0')) <= 9)
        {
            mantissa = mantissa * 10 + digit;
            i++;
        }
        int digits = i - start;
        int decimals = 0;
        if ((uint)i < (uint)text.Length && text[i] == '.')
        {
            int fraction = ++i;
            while ((uint)i < (uint)text.Length && (digit = (uint)(text[i] - '0')) <= 9)
            {
                mantissa = mantissa * 10 + digit;
                i++;
            }
            decimals = i - fraction;
            digits += decimals;
        }
        if (digits == 0 || digits > 15)
        {
            return -1;
        }
        double magnitude = decimals > 0 ? mantissa / NumAppend.Pow10[decimals] : mantissa;
        value = negative ? -magnitude : magnitude;
        return i;
    }
}
