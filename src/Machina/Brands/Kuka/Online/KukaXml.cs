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
            switch (c)
            {
                case '&':
                    sb.Append("&amp;");
                    break;
                case '<':
                    sb.Append("&lt;");
                    break;
                case '>':
                    sb.Append("&gt;");
                    break;
                case '"':
                    sb.Append("&quot;");
                    break;
                case '\'':
                    sb.Append("&apos;");
                    break;
                default:
                    sb.Append(c < ' ' || c == '\u007f' ? ' ' : c > '\u007e' ? '?' : c);
                    break;
            }
        }
        return sb;
    }
}
