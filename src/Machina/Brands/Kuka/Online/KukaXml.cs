using System.Text;

namespace Machina;

/// <summary>
/// Writes the XML of the KUKA link: element starts, attributes and text, with the five XML special characters escaped,
/// control characters as spaces and characters outside ASCII as '?' (KRL strings are ASCII), so user text can never break
/// the message (fix of bug K6).
/// </summary>
internal static class KukaXml
{
    /// <summary>Appends <c>&lt;name</c>.</summary>
    public static StringBuilder AppendStart(StringBuilder sb, string name) => sb.Append('<').Append(name);

    /// <summary>Appends <c> name="value"</c> with the value escaped.</summary>
    public static StringBuilder AppendAttribute(StringBuilder sb, string name, string value) =>
        AppendText(sb.Append(' ').Append(name).Append("=\""), value).Append('"');

    /// <summary>Appends <c> name="number"</c>, the number with at most 6 decimals, never in exponent form and never "-0".</summary>
    public static StringBuilder AppendAttribute(StringBuilder sb, string name, double value) =>
        sb.Append(' ').Append(name).Append("=\"").AppendFixed(value, 6).Append('"');

    /// <summary>Appends text escaped for an attribute value or element content.</summary>
    public static StringBuilder AppendText(StringBuilder sb, string text)
    {
        foreach (char c in text)
        {
            if (Escape(c, out char plain) is string entity)
            {
                sb.Append(entity);
            }
            else
            {
                sb.Append(plain);
            }
        }
        return sb;
    }

    /// <summary>
    /// How <paramref name="c"/> is written in an attribute value or element content: its entity (one of the five XML special
    /// characters), or null and <paramref name="plain"/>, the character itself, a control character as a space, one outside ASCII as '?'.
    /// </summary>
    public static string? Escape(char c, out char plain)
    {
        plain = c < ' ' || c == '\u007f' ? ' ' : c > '\u007e' ? '?' : c;
        return c switch
        {
            '&' => "&amp;",
            '<' => "&lt;",
            '>' => "&gt;",
            '"' => "&quot;",
            '\'' => "&apos;",
            _ => null,
        };
    }
}
