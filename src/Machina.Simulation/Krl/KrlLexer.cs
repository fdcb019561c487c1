using System.Globalization;

namespace Machina.Simulation.Krl;

/// <summary>
/// Splits a KRL file into tokens. A <c>;</c> starts a comment (folds included), lines that start with <c>&amp;</c> are file
/// attributes, statements end at the end of a line, names and keywords ignore case.
/// </summary>
internal static class KrlLexer
{
    private static readonly string[] TwoCharSymbols = ["==", "<>", "<=", ">="];

    /// <summary>
    /// The tokens of <paramref name="text"/>; throws <see cref="KrlLoadException"/> for a character KRL does not have, and
    /// <see cref="OperationCanceledException"/> at the next line once <paramref name="cancellation"/> is cancelled (a file of
    /// megabytes takes a while, longer on a loaded machine).
    /// </summary>
    public static List<KrlToken> Tokenize(string file, string text, CancellationToken cancellation = default)
    {
        var tokens = new List<KrlToken>();
        int line = 1;
        int i = 0;
        bool lineStart = true;
        while (i < text.Length)
        {
            char c = text[i];
            if (c == '\n')
            {
                cancellation.ThrowIfCancellationRequested();
                Add(tokens, new KrlToken(KrlTokenKind.EndOfLine, "", line));
                line++;
                i++;
                lineStart = true;
                continue;
            }
            if (c is ' ' or '\t' or '\r')
            {
                i++;
                continue;
            }
            if (c == ';' || (c == '&' && lineStart))
            {
                while (i < text.Length && text[i] != '\n')
                {
                    i++;
                }
                continue;
            }
            lineStart = false;
            int start = i;
            if (char.IsLetter(c) || c is '_' or '$')
            {
                i++;
                while (i < text.Length && (char.IsLetterOrDigit(text[i]) || text[i] is '_' or '$'))
                {
                    i++;
                }
                tokens.Add(new KrlToken(KrlTokenKind.Name, text[start..i], line));
            }
            else if (char.IsDigit(c) || (c == '.' && i + 1 < text.Length && char.IsDigit(text[i + 1])))
            {
                bool real = false;
                while (i < text.Length && char.IsDigit(text[i]))
                {
                    i++;
                }
                if (i < text.Length && text[i] == '.')
                {
                    real = true;
                    i++;
                    while (i < text.Length && char.IsDigit(text[i]))
                    {
                        i++;
                    }
                }
                if (i < text.Length && text[i] is 'e' or 'E' && i + 1 < text.Length && (char.IsDigit(text[i + 1]) || text[i + 1] is '+' or '-'))
                {
                    real = true;
                    i += 2;
                    while (i < text.Length && char.IsDigit(text[i]))
                    {
                        i++;
                    }
                }
                string number = text[start..i];
                if (!real && !int.TryParse(number, NumberStyles.None, CultureInfo.InvariantCulture, out _))
                {
                    throw new KrlLoadException(file, line, $"the number {number} is too large for an INT");
                }
                tokens.Add(new KrlToken(real ? KrlTokenKind.Real : KrlTokenKind.Int, number, line));
            }
            else if (c == '"')
            {
                i++;
                while (i < text.Length && text[i] != '"' && text[i] != '\n')
                {
                    i++;
                }
                if (i >= text.Length || text[i] != '"')
                {
                    throw new KrlLoadException(file, line, "a string is not closed with \" on its line");
                }
                tokens.Add(new KrlToken(KrlTokenKind.String, text[(start + 1)..i], line));
                i++;
            }
            else if (c == '\'')
            {
                // 'B0101' (binary) or 'H1F' (hexadecimal): an INT constant, as S and T of positions are written
                int close = text.IndexOf('\'', i + 1);
                string body = close > i ? text[(i + 1)..close] : "";
                int value;
                bool ok = body.Length > 1 && body[0] is 'B' or 'b'
                    ? body[1..].All(ch => ch is '0' or '1') && body.Length <= 33
                    : body.Length > 1 && body[0] is 'H' or 'h' && body[1..].All(char.IsAsciiHexDigit) && body.Length <= 9;
                if (!ok || body.Contains('\n', StringComparison.Ordinal))
                {
                    throw new KrlLoadException(file, line, "a ' starts a binary ('B0101') or hexadecimal ('H1F') constant");
                }
                value = body[0] is 'B' or 'b' ? Convert.ToInt32(body[1..], 2) : Convert.ToInt32(body[1..], 16);
                tokens.Add(new KrlToken(KrlTokenKind.Int, value.ToString(CultureInfo.InvariantCulture), line));
                i = close + 1;
            }
            else if (c == '#')
            {
                i++;
                while (i < text.Length && (char.IsLetterOrDigit(text[i]) || text[i] == '_'))
                {
                    i++;
                }
                if (i == start + 1)
                {
                    throw new KrlLoadException(file, line, "'#' must be followed by the name of an enumeration value");
                }
                tokens.Add(new KrlToken(KrlTokenKind.Enum, text[(start + 1)..i], line));
            }
            else if (i + 1 < text.Length && TwoCharSymbols.Contains(text.Substring(i, 2)))
            {
                tokens.Add(new KrlToken(KrlTokenKind.Symbol, text.Substring(i, 2), line));
                i += 2;
            }
            else if ("()[]{},:=<>+-*/.".Contains(c, StringComparison.Ordinal))
            {
                tokens.Add(new KrlToken(KrlTokenKind.Symbol, c.ToString(), line));
                i++;
            }
            else
            {
                throw new KrlLoadException(file, line, $"the character '{c}' is not part of KRL");
            }
        }
        Add(tokens, new KrlToken(KrlTokenKind.EndOfLine, "", line));
        tokens.Add(new KrlToken(KrlTokenKind.End, "", line));
        return tokens;
    }

    /// <summary>Adds an end of line unless the last token already is one (blank lines make no empty statements).</summary>
    private static void Add(List<KrlToken> tokens, KrlToken endOfLine)
    {
        if (tokens.Count > 0 && tokens[^1].Kind != KrlTokenKind.EndOfLine)
        {
            tokens.Add(endOfLine);
        }
    }
}
