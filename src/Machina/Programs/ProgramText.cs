using System.Text;

namespace Machina;

/// <summary>Text helpers shared by the program compilers: one-line texts and exact seconds.</summary>
internal static class ProgramText
{
    /// <summary>True for characters that end a line or are invisible controls: C0/C1 controls, DEL and the Unicode line and paragraph separators.</summary>
    internal static bool BreaksLine(char c) => char.IsControl(c) || c is '\u2028' or '\u2029';

    /// <summary>The text with every line break and control character replaced by a space, so that it stays on one line.</summary>
    internal static string OneLine(string text)
    {
        int first = -1;
        for (int i = 0; i < text.Length; i++)
        {
            if (BreaksLine(text[i]))
            {
                first = i;
                break;
            }
        }
        if (first < 0)
        {
            return text;
        }
        var sb = new StringBuilder(text.Length).Append(text, 0, first);
        for (int i = first; i < text.Length; i++)
        {
            sb.Append(BreaksLine(text[i]) ? ' ' : text[i]);
        }
        return sb.ToString();
    }

    /// <summary>Milliseconds as exact decimal seconds, never in exponent form: 1500 → "1.5", 1 → "0.001", 0 → "0".</summary>
    internal static string Seconds(long millis)
    {
        long whole = Math.DivRem(millis, 1000, out long rest);
        string text = whole.ToString(Num.Inv);
        return rest == 0 ? text : text + "." + rest.ToString("000", Num.Inv).TrimEnd('0');
    }
}
