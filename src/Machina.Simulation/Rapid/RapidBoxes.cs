namespace Machina.Simulation.Rapid;

/// <summary>
/// Shared boxes for the values a RAPID program computes most (booleans, small whole numbers, one-character strings), so that
/// evaluating <c>c = ";"</c>, <c>i + 1</c> or <c>StrPart(chunk, i, 1)</c> allocates nothing. The boxes are never mutated.
/// </summary>
internal static class RapidBoxes
{
    private const int Smallest = -16;
    private const int Largest = 1023;

    private static readonly object True = true;
    private static readonly object False = false;
    private static readonly object[] Numbers = [.. Enumerable.Range(Smallest, Largest - Smallest + 1).Select(i => (object)(double)i)];
    private static readonly string[] Characters = [.. Enumerable.Range(0, 256).Select(c => ((char)c).ToString())];

    /// <summary>The shared box of <paramref name="value"/>.</summary>
    public static object Bool(bool value) => value ? True : False;

    /// <summary>A box of <paramref name="value"/>: a shared one for whole numbers from -16 to 1023 (not -0), else a new one.</summary>
    public static object Num(double value)
    {
        if (value >= Smallest && value <= Largest && value == Math.Floor(value) && !(value == 0 && double.IsNegative(value)))
        {
            return Numbers[(int)value - Smallest];
        }
        return value;
    }

    /// <summary>The one-character string of <paramref name="c"/> (shared for Latin-1 characters).</summary>
    public static string Char(char c) => c < 256 ? Characters[c] : c.ToString();
}
