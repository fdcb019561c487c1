using System.Collections;
using System.Globalization;
using System.Text;

namespace Machina.Benchmarks;

/// <summary>
/// Writes the child's one-line JSON report by hand. <c>JsonSerializer</c> cost the child about 60 ms of its wall time after
/// the work (reflection and the just-in-time compilation of the serializer, in a fresh process), which the whole-process rows
/// counted as if a user's program paid it. Values: strings, booleans, integers, doubles (not finite: null), null, lists and
/// arrays of these, and dictionaries with string keys.
/// </summary>
internal static class ChildReport
{
    /// <summary>The JSON text of <paramref name="value"/>.</summary>
    internal static string Write(object? value)
    {
        var sb = new StringBuilder(1024);
        Append(sb, value);
        return sb.ToString();
    }

    private static void Append(StringBuilder sb, object? value)
    {
        switch (value)
        {
            case null:
                sb.Append("null");
                break;
            case string text:
                AppendString(sb, text);
                break;
            case bool flag:
                sb.Append(flag ? "true" : "false");
                break;
            case double number:
                if (double.IsFinite(number))
                {
                    sb.Append(number.ToString("R", CultureInfo.InvariantCulture));
                }
                else
                {
                    sb.Append("null");
                }
                break;
            case int or long:
                sb.Append(((IFormattable)value).ToString(null, CultureInfo.InvariantCulture));
                break;
            case IDictionary dictionary:
                sb.Append('{');
                bool firstEntry = true;
                foreach (DictionaryEntry entry in dictionary)
                {
                    sb.Append(firstEntry ? "" : ",");
                    firstEntry = false;
                    AppendString(sb, (string)entry.Key);
                    sb.Append(':');
                    Append(sb, entry.Value);
                }
                sb.Append('}');
                break;
            case IEnumerable items:
                sb.Append('[');
                bool firstItem = true;
                foreach (object? item in items)
                {
                    sb.Append(firstItem ? "" : ",");
                    firstItem = false;
                    Append(sb, item);
                }
                sb.Append(']');
                break;
            default:
                throw new ArgumentException($"The child's report cannot hold a {value.GetType().Name}.", nameof(value));
        }
    }

    private static void AppendString(StringBuilder sb, string text)
    {
        sb.Append('"');
        foreach (char c in text)
        {
            switch (c)
            {
                case '"':
                    sb.Append("\\\"");
                    break;
                case '\\':
                    sb.Append("\\\\");
                    break;
                case < ' ':
                    sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                    break;
                default:
                    sb.Append(c);
                    break;
            }
        }
        sb.Append('"');
    }
}
