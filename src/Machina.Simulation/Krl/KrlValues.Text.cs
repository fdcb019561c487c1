namespace Machina.Simulation.Krl;

/// <summary>Writing text into a CHAR array (EKI_GetString's row, a STRING's assignment).</summary>
internal static partial class KrlValues
{
    /// <summary>
    /// Copies <paramref name="text"/> into a CHAR array (the rest unset); characters beyond its size are cut. An element that
    /// already holds the character's shared box is not stored again: the driver's EKI_GetString writes a slot's 80 characters at
    /// every action, most of them the same unset ones, and each store of a reference is a write barrier. The row is a span (one
    /// range check, none per element) and the unset rest is a compare against one box: its 70-odd elements cost a few
    /// instructions each, where each looked its box up again (a call, a table read, two range checks).
    /// </summary>
    public static void SetText(object[] items, int start, int length, string text)
    {
        Span<object> row = items.AsSpan(start, length);
        int written = Math.Min(text.Length, row.Length);
        for (int i = 0; i < written; i++)
        {
            object box = Box(text[i]);
            if (!ReferenceEquals(row[i], box))
            {
                row[i] = box;
            }
        }
        object unset = Chars[0];
        for (int i = written; i < row.Length; i++)
        {
            if (!ReferenceEquals(row[i], unset))
            {
                row[i] = unset;
            }
        }
    }
}
