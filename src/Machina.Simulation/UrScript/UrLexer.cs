using System.Globalization;

namespace Machina.Simulation.UrScript;

/// <summary>Splits URScript text into tokens: names, numbers, strings, symbols and line ends; comments (#) are dropped.</summary>
internal static class UrLexer
{
    /// <summary>The tokens of <paramref name="text"/>, ending with <see cref="UrTokenKind.End"/>.</summary>
    /// <exception cref="UrCompileException">A character that is not URScript, or a string that does not end on its line.</exception>
    public static List<UrToken> Tokenize(string text) => [.. Tokens(text)];

    /// <summary>
    /// The tokens of <paramref name="text"/> one at a time, ending with <see cref="UrTokenKind.End"/> (a mistake throws when
    /// its token is reached), so that a parser never holds the tokens of a whole long program.
    /// </summary>
    public static IEnumerable<UrToken> Tokens(string text)
    {
        var words = new TextCache(); // one string per distinct name or number: a long program repeats few of them
        int line = 1, lineStart = 0, i = 0;
        int open = 0; // brackets open: a statement goes on over line ends inside parentheses or a list, as on a controller
        bool operatorLast = false; // the last token is a binary operator: the expression goes on on the next line
        while (i < text.Length)
        {
            char c = text[i];
            int column = i - lineStart + 1;
            if (c == '\n')
            {
                if (open == 0 && !operatorLast)
                {
                    yield return new UrToken(UrTokenKind.Newline, "\n", line, column);
                }
                line++;
                lineStart = ++i;
            }
            else if (c == ' ' || c == '\t' || c == '\r')
            {
                i++;
            }
            else if (c == '#')
            {
                while (i < text.Length && text[i] != '\n')
                {
                    i++;
                }
            }
            else if (char.IsAsciiLetter(c) || c == '_')
            {
                int start = i;
                while (i < text.Length && (char.IsAsciiLetterOrDigit(text[i]) || text[i] == '_'))
                {
                    i++;
                }
                string name = words.Get(text, start, i - start);
                operatorLast = name is "and" or "or";
                yield return new UrToken(UrTokenKind.Name, name, line, column);
            }
            else if (char.IsAsciiDigit(c) || (c == '.' && i + 1 < text.Length && char.IsAsciiDigit(text[i + 1])))
            {
                (UrToken number, i) = ReadNumber(text, i, line, column, words);
                operatorLast = false;
                yield return number;
            }
            else if (c == '"' || c == '\'')
            {
                int start = ++i;
                while (i < text.Length && text[i] != c && text[i] != '\n')
                {
                    i++;
                }
                if (i >= text.Length || text[i] != c)
                {
                    throw new UrCompileException(line, "the string does not end on its line");
                }
                operatorLast = false;
                yield return new UrToken(UrTokenKind.String, text[start..i], line, column);
                i++;
            }
            else if (i + 1 < text.Length && text[i + 1] == '=' && c is '=' or '!' or '<' or '>')
            {
                operatorLast = true;
                yield return new UrToken(UrTokenKind.Symbol, c switch { '=' => "==", '!' => "!=", '<' => "<=", _ => ">=" }, line, column);
                i += 2;
            }
            else if (Symbols.IndexOf(c, StringComparison.Ordinal) is int symbol and >= 0)
            {
                open = c is '(' or '[' ? open + 1 : c is ')' or ']' ? Math.Max(0, open - 1) : open;
                operatorLast = c is '+' or '-' or '*' or '/' or '%' or '<' or '>' or '='; // after '=' too: the value may be on the next line
                yield return new UrToken(UrTokenKind.Symbol, SymbolTexts[symbol], line, column);
                i++;
            }
            else
            {
                throw new UrCompileException(line, $"unexpected character '{c}'");
            }
        }
        yield return new UrToken(UrTokenKind.Newline, "\n", line, i - lineStart + 1);
        yield return new UrToken(UrTokenKind.End, "", line, i - lineStart + 1);
    }

    private const string Symbols = "+-*/%=<>()[],:";

    /// <summary>The text of each single-character symbol, made once.</summary>
    private static readonly string[] SymbolTexts = [.. Symbols.Select(c => c.ToString())];

    private static (UrToken Token, int End) ReadNumber(string text, int i, int line, int column, TextCache words)
    {
        int start = i;
        bool isFloat = false;
        while (i < text.Length && char.IsAsciiDigit(text[i]))
        {
            i++;
        }
        if (i < text.Length && text[i] == '.')
        {
            isFloat = true;
            i++;
            while (i < text.Length && char.IsAsciiDigit(text[i]))
            {
                i++;
            }
        }
        if (i < text.Length && (text[i] == 'e' || text[i] == 'E'))
        {
            int save = i++;
            if (i < text.Length && (text[i] == '+' || text[i] == '-'))
            {
                i++;
            }
            if (i < text.Length && char.IsAsciiDigit(text[i]))
            {
                isFloat = true;
                while (i < text.Length && char.IsAsciiDigit(text[i]))
                {
                    i++;
                }
            }
            else
            {
                i = save;
            }
        }
        string literal = words.Get(text, start, i - start);
        double value = words.Number(literal);
        if (!isFloat && (value > int.MaxValue + 1.0))
        {
            throw new UrCompileException(line, $"the integer {literal} is out of range");
        }
        return (new UrToken(isFloat ? UrTokenKind.Float : UrTokenKind.Int, literal, line, column, value), i);
    }

    /// <summary>Gives the same string for the same characters, so that a name or number repeated on many lines is stored once.</summary>
    private sealed class TextCache
    {
        private readonly Dictionary<string, string> _texts = new(StringComparer.Ordinal);
        private readonly Dictionary<string, double> _numbers = new(ReferenceEqualityComparer.Instance);

        /// <summary>The value of a number literal given by <see cref="Get"/> (parsed once per distinct literal).</summary>
        public double Number(string literal)
        {
            if (!_numbers.TryGetValue(literal, out double value))
            {
                value = double.Parse(literal, NumberStyles.Float, CultureInfo.InvariantCulture);
                _numbers[literal] = value;
            }
            return value;
        }

        public string Get(string text, int start, int length)
        {
#if NET9_0_OR_GREATER
            var lookup = _texts.GetAlternateLookup<ReadOnlySpan<char>>();
            ReadOnlySpan<char> span = text.AsSpan(start, length);
            if (lookup.TryGetValue(span, out string? known))
            {
                return known;
            }
            string made = span.ToString();
#else
            string made = text.Substring(start, length);
            if (_texts.TryGetValue(made, out string? known))
            {
                return known;
            }
#endif
            _texts[made] = made;
            return made;
        }
    }
}
