using System.Globalization;
using System.Text;

namespace Machina;

/// <summary>
/// Text that came over a network (a controller's answer, a client's request) made safe to show in a terminal or a log: control
/// characters (C0, DEL, C1: escape sequences that move the cursor, recolour or retitle a terminal) and the Unicode direction
/// overrides are written as escapes (<c>\x1b</c>, <c>\u202e</c>); line breaks and tabs as <c>\n</c>, <c>\r</c>, <c>\t</c>, so one
/// message stays one line. Everything else is kept as it is.
/// </summary>
internal static class PrintableText
{
    /// <summary>
    /// <paramref name="text"/> with every character a terminal would act on written as an escape; with <paramref name="keepLines"/>,
    /// line feeds and tabs are kept (a message of several lines of the library's own).
    /// </summary>
    internal static string Of(string text, bool keepLines = false)
    {
        int first = 0;
        while (first < text.Length && Kept(text[first], keepLines))
        {
            first++;
        }
        if (first == text.Length)
        {
            return text;
        }
        var result = new StringBuilder(text.Length + 16);
        result.Append(text, 0, first);
        for (int i = first; i < text.Length; i++)
        {
            char c = text[i];
            if (Kept(c, keepLines))
            {
                result.Append(c);
                continue;
            }
            result.Append(c switch
            {
                '\n' => "\\n",
                '\r' => "\\r",
                '\t' => "\\t",
                < '\u0100' => "\\x" + ((int)c).ToString("x2", CultureInfo.InvariantCulture),
                _ => "\\u" + ((int)c).ToString("x4", CultureInfo.InvariantCulture),
            });
        }
        return result.ToString();
    }

    private static bool Kept(char c, bool keepLines) => IsPrintable(c) || (keepLines && c is '\n' or '\t');

    /// <summary>False for the characters a terminal acts on: C0 controls, DEL, C1 controls and the bidirectional overrides and isolates.</summary>
    private static bool IsPrintable(char c) =>
        c >= ' ' && c is not ('\u007f' or (>= '\u0080' and <= '\u009f') or '\u200e' or '\u200f' or (>= '\u202a' and <= '\u202e') or (>= '\u2066' and <= '\u2069'));
}
