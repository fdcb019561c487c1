using System.Globalization;

namespace Machina.Simulation;

/// <summary>
/// Reads request statements the way the RAPID driver does (spec online §6.7): optional <c>@id</c>, a numeric code,
/// an optional quoted text, then up to 11 numbers; missing numbers read as 0. Used by the virtual controller.
/// </summary>
internal static class AbbRequestParser
{
    /// <summary>Parses one statement (without its <c>;</c>); on failure returns false and a reason like the driver's pendant message.</summary>
    public static bool TryParse(ReadOnlySpan<char> statement, out AbbRequest request, out string? error)
    {
        request = default;
        var rest = statement.Trim();
        // .NET number parsing skips trailing NUL characters, RAPID's StrToVal does not: refuse every control character
        // other than the tab separator before reading any token.
        if (ContainsControlOtherThanTab(rest))
        {
            error = $"received a control character in \"{Printable(statement)}\"";
            return false;
        }
        if (rest.Length < 2 && !(rest.Length == 1 && char.IsAsciiDigit(rest[0])))
        {
            error = $"statement too short: \"{statement}\"";
            return false;
        }
        int id = 0;
        if (rest[0] == '@')
        {
            var idText = NextToken(ref rest, skip: 1);
            if (!TryInteger(idText, out id) || id < 0 || id > AbbRequest.MaxId)
            {
                error = $"received corrupt id \"{idText}\"";
                return false;
            }
        }
        var codeText = NextToken(ref rest, skip: 0);
        if (!TryInteger(codeText, out int code))
        {
            error = $"received corrupt message \"{statement}\"";
            return false;
        }
        string? text = null;
        rest = rest.TrimStart();
        if (rest.Length > 0 && rest[0] == '"')
        {
            int close = rest[1..].IndexOf('"');
            if (close < 0)
            {
                error = $"missing closing quote in \"{statement}\"";
                return false;
            }
            text = rest.Slice(1, close).ToString();
            rest = rest[(close + 2)..];
        }
        Span<double> values = stackalloc double[AbbRequest.MaxParameters];
        int count = 0;
        while (true)
        {
            var token = NextToken(ref rest, skip: 0);
            if (token.IsEmpty)
            {
                break;
            }
            if (count == AbbRequest.MaxParameters)
            {
                error = $"more than {AbbRequest.MaxParameters} parameters in \"{statement}\"";
                return false;
            }
            if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out values[count]) || !double.IsFinite(values[count]))
            {
                error = $"received corrupt parameter \"{token}\"";
                return false;
            }
            count++;
        }
        try
        {
            request = new AbbRequest(id, code, text, values[..count]);
        }
        catch (ArgumentException e)
        {
            error = e.Message;
            return false;
        }
        error = null;
        return true;
    }

    private static bool ContainsControlOtherThanTab(ReadOnlySpan<char> text)
    {
        foreach (char c in text)
        {
            if (char.IsControl(c) && c != '\t')
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>The statement with control characters shown as <c>\uXXXX</c>, for a readable reason.</summary>
    private static string Printable(ReadOnlySpan<char> text)
    {
        var sb = new System.Text.StringBuilder(text.Length);
        foreach (char c in text)
        {
            sb.Append(char.IsControl(c) ? $"\\u{(int)c:x4}" : c);
        }
        return sb.ToString();
    }

    private static ReadOnlySpan<char> NextToken(ref ReadOnlySpan<char> rest, int skip)
    {
        rest = rest[skip..].TrimStart();
        int end = rest.IndexOfAny(' ', '\t');
        if (end < 0)
        {
            end = rest.Length;
        }
        var token = rest[..end];
        rest = rest[end..];
        return token;
    }

    private static bool TryInteger(ReadOnlySpan<char> text, out int value)
    {
        // RAPID reads every token as a num; accept "12" and "12.0" but not "12.5".
        if (double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) && v == Math.Floor(v) && Math.Abs(v) <= int.MaxValue)
        {
            value = (int)v;
            return true;
        }
        value = 0;
        return false;
    }
}
