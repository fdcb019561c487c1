namespace Machina;

/// <summary>
/// The instruction names closest to a mistyped one ("Moov" → "Move"), for the "did you mean" of the instruction reader's
/// error: letters added, dropped, changed or swapped, ignoring letter case.
/// </summary>
internal static class InstructionSuggestion
{
    /// <summary>The known names nearest to <paramref name="name"/> (at most three, in order), or none when nothing is close.</summary>
    internal static IReadOnlyList<string> For(string name)
    {
        int limit = name.Length <= 4 ? 1 : name.Length <= 8 ? 2 : 3;
        var best = new List<string>();
        int bestDistance = limit + 1;
        foreach (string known in InstructionCatalog.Names.Order(StringComparer.Ordinal))
        {
            if (Math.Abs(known.Length - name.Length) > limit)
            {
                continue;
            }
            int distance = Distance(name, known);
            if (distance < bestDistance)
            {
                bestDistance = distance;
                best.Clear();
            }
            if (distance == bestDistance && best.Count < 3)
            {
                best.Add(known);
            }
        }
        return best;
    }

    /// <summary>The names as "did you mean" text: <c>"Move"</c>, <c>"Move" or "Wait"</c>.</summary>
    internal static string Quoted(IReadOnlyList<string> names) =>
        names.Count == 1 ? $"\"{names[0]}\"" : string.Join(", ", names.SkipLast(1).Select(n => $"\"{n}\"")) + $" or \"{names[^1]}\"";

    /// <summary>Edits (insert, delete, change, swap two neighbours) that turn <paramref name="a"/> into <paramref name="b"/>, ignoring case.</summary>
    private static int Distance(string a, string b)
    {
        int[,] d = new int[a.Length + 1, b.Length + 1];
        for (int i = 0; i <= a.Length; i++)
        {
            d[i, 0] = i;
        }
        for (int j = 0; j <= b.Length; j++)
        {
            d[0, j] = j;
        }
        for (int i = 1; i <= a.Length; i++)
        {
            for (int j = 1; j <= b.Length; j++)
            {
                int cost = char.ToUpperInvariant(a[i - 1]) == char.ToUpperInvariant(b[j - 1]) ? 0 : 1;
                int value = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
                if (i > 1 && j > 1 && char.ToUpperInvariant(a[i - 1]) == char.ToUpperInvariant(b[j - 2])
                    && char.ToUpperInvariant(a[i - 2]) == char.ToUpperInvariant(b[j - 1]))
                {
                    value = Math.Min(value, d[i - 2, j - 2] + 1);
                }
                d[i, j] = value;
            }
        }
        return d[a.Length, b.Length];
    }
}
