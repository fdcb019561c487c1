using System.Globalization;

namespace Machina;

/// <summary>A count with its noun for people-facing text: "1 action", "2 actions" (never "1 actions").</summary>
internal static class Counted
{
    /// <summary>
    /// <paramref name="count"/> and <paramref name="noun"/> (singular), with an "s" when the count is not 1; <paramref name="plural"/>
    /// replaces that for a noun whose plural is not the singular and an "s".
    /// </summary>
    internal static string Of(long count, string noun, string? plural = null) =>
        count.ToString(CultureInfo.InvariantCulture) + " " + (count == 1 ? noun : plural ?? noun + "s");

    /// <summary>The noun alone, singular or plural for <paramref name="count"/> (for "N were sent" sentences that put the count elsewhere).</summary>
    internal static string Noun(long count, string noun, string? plural = null) => count == 1 ? noun : plural ?? noun + "s";
}
