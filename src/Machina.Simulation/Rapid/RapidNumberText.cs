namespace Machina.Simulation.Rapid;

/// <summary>
/// The commonest number text a program converts (StrToVal of "751", "-12.5"), read without the runtime's general parser: a sign, at
/// most 15 digits and a decimal point between digits. Such a number is its digits (exact below 2^53) divided by a power of ten (exact up to
/// 10^22), and one division of exact numbers is correctly rounded, so the result is the double the general parser gives (the "fast
/// path" of Clinger, "How to read floating point numbers accurately", 1990). Other text (exponents, more digits, a '+') goes to the
/// general parser.
/// </summary>
internal static class RapidNumberText
{
    private const int MaxDigits = 15;

    private static readonly double[] PowersOfTen = [1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15];

    /// <summary>
    /// Reads <paramref name="text"/> when it is <c>-?digits(.digits)?</c> with at most 15 digits; false (and 0) for any other text, which
    /// the caller then gives to <see cref="double.TryParse(string?, System.Globalization.NumberStyles, IFormatProvider?, out double)"/>.
    /// </summary>
    public static bool TryParsePlain(ReadOnlySpan<char> text, out double value)
    {
        value = 0;
        int i = text.Length > 0 && text[0] == '-' ? 1 : 0;
        long digits = 0;
        int count = 0, decimals = 0, point = -1;
        for (; i < text.Length; i++)
        {
            char c = text[i];
            if (c is >= '0' and <= '9')
            {
                if (++count > MaxDigits)
                {
                    return false;
                }
                digits = digits * 10 + (c - '0');
                decimals += point >= 0 ? 1 : 0;
            }
            else if (c == '.' && point < 0 && count > 0)
            {
                point = i;
            }
            else
            {
                return false;
            }
        }
        if (count == 0 || (point >= 0 && decimals == 0))
        {
            return false; // "", "-", "1.": the general parser decides
        }
        double magnitude = decimals == 0 ? digits : digits / PowersOfTen[decimals];
        value = text[0] == '-' ? -magnitude : magnitude; // "-0" is -0, as the general parser reads it
        return true;
    }
}
