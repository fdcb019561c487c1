using System.Text;

namespace Machina;

/// <summary>Makes user text safe inside G-code lines: it can neither end a comment early nor start a new command.</summary>
internal static class GCodeText
{
    /// <summary>Text for a <c>;</c> comment: line breaks (also Unicode line separators) and other control characters become spaces.</summary>
    internal static string Comment(string text) => ProgramText.OneLine(text);

    /// <summary>Text for a message shown by the printer: as <see cref="Comment"/>, ';' becomes ',' and parentheses become brackets, since they would start a comment, and '*' becomes '+', since Marlin cuts a
    /// message at the first '*' (where a line checksum starts).</summary>
    internal static string Message(string text) => Replace(text);

    private static string Replace(string text)
    {
        StringBuilder? sb = null;
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            char safe = ProgramText.BreaksLine(c) ? ' ' : c switch { ';' => ',', '(' => '[', ')' => ']', '*' => '+', _ => c };
            if (safe != c && sb is null)
            {
                sb = new StringBuilder(text.Length);
                sb.Append(text, 0, i);
            }
            sb?.Append(safe);
        }
        return sb?.ToString() ?? text;
    }
}
