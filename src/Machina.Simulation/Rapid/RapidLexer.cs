using System.Globalization;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Splits a RAPID module into tokens: names, numbers (<c>9E9</c>, <c>0.5</c>), strings (<c>""</c> is a quote, <c>\\</c> a
/// backslash, <c>\hh</c> a character by its hexadecimal code) and symbols; <c>!</c> starts a comment to the end of the line.
/// </summary>
internal static class RapidLexer
{
    private const string Singles = "+-*/<>=()[]{},;:.\\|%";

    private static readonly string[] SingleTexts = [.. Singles.Select(c => c.ToString())];

    /// <summary>The tokens of <paramref name="text"/>, ending with an <see cref="RapidTokenKind.End"/> token.</summary>
    /// <exception cref="RapidLoadException">A character that RAPID does not have, or an unterminated string.</exception>
    public static List<RapidToken> Tokenize(string text)
    {
        var tokens = new List<RapidToken>(Math.Min(text.Length / 4, 1 << 16));
        int line = 1, i = 0, n = text.Length;
        while (i < n)
        {
            char c = text[i];
            if (c == '\n')
            {
                line++;
                i++;
            }
            else if (c is ' ' or '\t' or '\r' or '\f')
            {
                i++;
            }
            else if (c == '!')
            {
                while (i < n && text[i] != '\n')
                {
                    i++;
                }
            }
            else if (char.IsAsciiLetter(c))
            {
                int start = i;
                while (i < n && (char.IsAsciiLetterOrDigit(text[i]) || text[i] == '_'))
                {
                    i++;
                }
                tokens.Add(new RapidToken(RapidTokenKind.Name, text[start..i], 0, line));
            }
            else if (char.IsAsciiDigit(c) || (c == '.' && i + 1 < n && char.IsAsciiDigit(text[i + 1])))
            {
                tokens.Add(Number(text, ref i, line));
            }
            else if (c == '"')
            {
                tokens.Add(String(text, ref i, line));
            }
            else
            {
                char d = i + 1 < n ? text[i + 1] : '\0';
                string? two = (c, d) switch { (':', '=') => ":=", ('<', '>') => "<>", ('<', '=') => "<=", ('>', '=') => ">=", _ => null };
                int single = Singles.IndexOf(c, StringComparison.Ordinal);
                if (two is not null)
                {
                    tokens.Add(new RapidToken(RapidTokenKind.Symbol, two, 0, line));
                    i += 2;
                }
                else if (single >= 0)
                {
                    tokens.Add(new RapidToken(RapidTokenKind.Symbol, SingleTexts[single], 0, line));
                    i++;
                }
                else
                {
                    throw new RapidLoadException(line, RapidLoadException.Syntax($"unexpected character '{c}'"));
                }
            }
        }
        tokens.Add(new RapidToken(RapidTokenKind.End, "end of module", 0, line));
        return tokens;
    }

    private static RapidToken Number(string text, ref int i, int line)
    {
        int start = i, n = text.Length;
        while (i < n && char.IsAsciiDigit(text[i]))
        {
            i++;
        }
        if (i < n && text[i] == '.')
        {
            i++;
            while (i < n && char.IsAsciiDigit(text[i]))
            {
                i++;
            }
        }
        if (i < n && text[i] is 'e' or 'E')
        {
            int mark = i++;
            if (i < n && text[i] is '+' or '-')
            {
                i++;
            }
            if (i < n && char.IsAsciiDigit(text[i]))
            {
                while (i < n && char.IsAsciiDigit(text[i]))
                {
                    i++;
                }
            }
            else
            {
                i = mark;
            }
        }
        double value = double.Parse(text.AsSpan(start, i - start), NumberStyles.Float, CultureInfo.InvariantCulture);
        return new RapidToken(RapidTokenKind.Number, "number", value, line);
    }

    private static RapidToken String(string text, ref int i, int line)
    {
        var value = new StringBuilder();
        i++;
        while (true)
        {
            if (i >= text.Length || text[i] == '\n')
            {
                throw new RapidLoadException(line, RapidLoadException.Syntax("string not terminated"));
            }
            char c = text[i];
            if (c == '"')
            {
                if (i + 1 < text.Length && text[i + 1] == '"')
                {
                    value.Append('"');
                    i += 2;
                    continue;
                }
                i++;
                break;
            }
            if (c == '\\' && i + 1 < text.Length && text[i + 1] == '\\')
            {
                value.Append('\\');
                i += 2;
            }
            else if (c == '\\' && i + 2 < text.Length && char.IsAsciiHexDigit(text[i + 1]) && char.IsAsciiHexDigit(text[i + 2]))
            {
                value.Append((char)int.Parse(text.AsSpan(i + 1, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture));
                i += 3;
            }
            else
            {
                value.Append(c);
                i++;
            }
        }
        return new RapidToken(RapidTokenKind.String, value.ToString(), 0, line);
    }
}
