namespace Machina.Simulation.Krl;

/// <summary>
/// Plain decimal text (an optional sign, digits, an optional point and digits: <c>-12.375</c>) read as a REAL without the
/// culture-aware number parser, for what EthernetKRL hands a program (EKI_GetReal: seven values an action of the Machina
/// driver). Only text whose digits make a whole number of at most 2^53 with at most 22 digits after the point is read here:
/// that number and the power of ten are exact doubles, so their quotient is the correctly rounded value, the same double as
/// <see cref="double.Parse(string, IFormatProvider)"/> gives (Clinger's fast path). Anything else (an exponent, spaces, more
/// digits, no digit) is left to <see cref="double.Parse(string, IFormatProvider)"/>.
/// </summary>
internal static class KrlDecimalText
{
    private const ulong MaxExact = 1UL << 53;

    private static readonly double[] PowersOfTen =
    [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    ];

    /// <summary>Reads <paramref name="text"/> when it is plain decimal text within the fast path's bounds; false otherwise.</summary>
    public static bool TryRead(string text, out double value)
    {
        value = 0;
        int i = 0;
        bool negative = false;
        if (i < text.Length && text[i] is '-' or '+')
        {
            negative = text[i] == '-';
            i++;
        }
        ulong whole = 0;
        int digits = 0, decimals = 0;
        bool point = false;
        for (; i < text.Length; i++)
        {
            char c = text[i];
            if (c == '.' && !point)
            {
                point = true;
                continue;
            }
            uint digit = (uint)(c - '0');
            if (digit > 9)
            {
                return false;
            }
            if (++digits > 19)
            {
                return false;
            }
            whole = whole * 10 + digit;
            if (point)
            {
                decimals++;
            }
        }
        if (digits == 0 || whole > MaxExact || decimals >= PowersOfTen.Length)
        {
            return false;
        }
        double magnitude = whole / PowersOfTen[decimals];
        value = negative ? -magnitude : magnitude;
        return true;
    }
}
