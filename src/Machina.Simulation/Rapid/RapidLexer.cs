using System.Globalization;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Splits a RAPID module into tokens: names, numbers (<c>9E9</c>, <c>0.5</c>), strings (<c>""</c> is a quote, <c>\\</c> a
/// backslash, <c>\hh</c> a character by its hexadecimal code) and symbols; <c>!</c> starts a comment to the end of the line.
/// </summary>
internal sealed class RapidLexer(string text)
{
    private const string Singles = "+-*/<>=()[]{},;:.\\|%";

    private static readonly string[] SingleTexts = [.. Singles.Select(c => c.ToString())];

    private readonly Dictionary<int, string> _names = [];
    private int _line = 1;
    private int _i;

    /// <summary>The tokens of <paramref name="text"/>, ending with an <see cref="RapidTokenKind.End"/> token.</summary>
    /// <exception cref="RapidLoadException">A character that RAPID does not have, or an unterminated string.</exception>
    public static List<RapidToken> Tokenize(string text)
    {
        var lexer = new RapidLexer(text);
        var tokens = new List<RapidToken>();
        RapidToken token;
        do
        {
            token = lexer.Next();
            tokens.Add(token);
        }
        while (token.Kind != RapidTokenKind.End);
        return tokens;
    }

    /// <summary>The next token (an <see cref="RapidTokenKind.End"/> token at the end, again and again).</summary>
    /// <exception cref="RapidLoadException">A character that RAPID does not have, or an unterminated string.</exception>
    public RapidToken Next()
    {
        int n = text.Length;
        while (_i < n)
        {
            char c = text[_i];
            if (c == '\n')
            {
                _line++;
                _i++;
            }
            else if (c is ' ' or '\t' or '\r' or '\f')
            {
                _i++;
            }
            else if (c == '!')
            {
                while (_i < n && text[_i] != '\n')
                {
                    _i++;
                }
            }
            else if (char.IsAsciiLetter(c))
            {
                int start = _i;
                while (_i < n && (char.IsAsciiLetterOrDigit(text[_i]) || text[_i] == '_'))
                {
                    _i++;
                }
                return new RapidToken(RapidTokenKind.Name, Name(start, _i - start), 0, _line);
            }
            else if (char.IsAsciiDigit(c) || (c == '.' && _i + 1 < n && char.IsAsciiDigit(text[_i + 1])))
            {
                return Number(text, ref _i, _line);
            }
            else if (c == '"')
            {
                return String(text, ref _i, _line);
            }
            else
            {
                char d = _i + 1 < n ? text[_i + 1] : '\0';
                string? two = (c, d) switch { (':', '=') => ":=", ('<', '>') => "<>", ('<', '=') => "<=", ('>', '=') => ">=", _ => null };
                int single = Singles.IndexOf(c, StringComparison.Ordinal);
                if (two is not null)
                {
                    _i += 2;
                    return new RapidToken(RapidTokenKind.Symbol, two, 0, _line);
                }
                if (single >= 0)
                {
                    _i++;
                    return new RapidToken(RapidTokenKind.Symbol, SingleTexts[single], 0, _line);
                }
                throw new RapidLoadException(_line, RapidLoadException.Syntax($"unexpected character '{c}'"));
            }
        }
        return new RapidToken(RapidTokenKind.End, "end of module", 0, _line);
    }

    /// <summary>The name at <paramref name="start"/>, one string per spelling: a long module repeats few names.</summary>
    private string Name(int start, int length)
    {
        ReadOnlySpan<char> span = text.AsSpan(start, length);
        int key = string.GetHashCode(span);
        if (_names.TryGetValue(key, out string? known) && span.SequenceEqual(known))
        {
            return known;
        }
        string name = span.ToString();
        _names[key] = name;
        return name;
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
        // A literal ends on its line: the rest of the line is all it may take.
        int lineEnd = text.IndexOf('\n', i);
        int at = 0;
        string value = StringLiteral(text.AsSpan(i, (lineEnd < 0 ? text.Length : lineEnd) - i), ref at)
            ?? throw new RapidLoadException(line, RapidLoadException.Syntax("string not terminated"));
        i += at;
        return new RapidToken(RapidTokenKind.String, value, 0, line);
    }

    /// <summary>
    /// The value of the string literal that starts at <paramref name="at"/> (its opening quote): <c>""</c> is a quote, <c>\\</c> a
    /// backslash, <c>\hh</c> the character of hexadecimal code hh. <paramref name="at"/> moves past its closing quote; null when there
    /// is no literal there or it has no closing quote. The lexer's and StrToVal's reading of a string.
    /// </summary>
    internal static string? StringLiteral(ReadOnlySpan<char> text, ref int at)
    {
        if (at >= text.Length || text[at] != '"')
        {
            return null;
        }
        var value = new StringBuilder();
        int i = at + 1;
        while (i < text.Length)
        {
            char c = text[i];
            if (c == '"')
            {
                if (i + 1 < text.Length && text[i + 1] == '"')
                {
                    value.Append('"');
                    i += 2;
                    continue;
                }
                at = i + 1;
                return value.ToString();
            }
            if (c == '\\' && i + 1 < text.Length && text[i + 1] == '\\')
            {
                value.Append('\\');
                i += 2;
            }
            else if (c == '\\' && i + 2 < text.Length && char.IsAsciiHexDigit(text[i + 1]) && char.IsAsciiHexDigit(text[i + 2]))
            {
                value.Append((char)int.Parse(text.Slice(i + 1, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture));
                i += 3;
            }
            else
            {
                value.Append(c);
                i++;
            }
        }
        return null;
    }
}
