using System.Globalization;

namespace Machina;

/// <summary>
/// What the RAPID driver can read of a request after its <c>@id</c> (ParseChunk in drivers/abb/machina_abb_driver.mod): a
/// whole-number code, at most one quoted text, then at most 11 numbers, each token a RAPID <c>num</c> (StrToVal: a 32-bit
/// float). Anything else makes the strict driver stop, or is dropped without an acknowledgement. Used by
/// <see cref="AbbRequest.WhyStatementCannotBeSent"/>, so that the encoder sends nothing the driver cannot run (issue 28).
/// </summary>
internal static class AbbStatementGrammar
{
    /// <summary>Why the driver cannot read <paramref name="statement"/> (plain ASCII, no ';', trimmed), or null when it can.</summary>
    public static string? WhyDriverCannotRead(string statement)
    {
        int numbers = 0;
        bool hasCode = false, hasText = false;
        int i = 0;
        while (i < statement.Length)
        {
            char c = statement[i];
            if (c is ' ' or '\t')
            {
                i++;
                continue;
            }
            if (c == '"')
            {
                int close = statement.IndexOf('"', i + 1);
                if (close < 0)
                {
                    return "a quote is never closed.";
                }
                if (!hasCode)
                {
                    return "the text comes before the instruction code.";
                }
                if (hasText)
                {
                    return "there is more than one quoted text.";
                }
                if (numbers > 0)
                {
                    return "the quoted text must come right after the instruction code.";
                }
                if (close - i - 1 > AbbRequest.MaxTextLength)
                {
                    return $"the quoted text has {close - i - 1} characters.";
                }
                hasText = true;
                i = close + 1;
                continue;
            }
            int end = i;
            while (end < statement.Length && statement[end] is not (' ' or '\t' or '"'))
            {
                end++;
            }
            string token = statement[i..end];
            i = end;
            if (token.Contains('@', StringComparison.Ordinal))
            {
                return "'@' marks the id, which Machina writes itself.";
            }
            if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || !double.IsFinite(value) || token.Length > AbbRequest.MaxTextLength)
            {
                return hasCode ? $"\"{Short(token)}\" is not a number." : $"\"{Short(token)}\" is not a numeric instruction code.";
            }
            if (Math.Abs(value) > float.MaxValue)
            {
                return $"{Short(token)} is beyond what a RAPID number holds (±3.4E+38).";
            }
            if (!hasCode)
            {
                if (value != Math.Floor(value) || Math.Abs(value) > int.MaxValue)
                {
                    return $"the instruction code {Short(token)} is not a whole number.";
                }
                hasCode = true;
                continue;
            }
            if (++numbers > AbbRequest.MaxParameters)
            {
                return $"there are more than {AbbRequest.MaxParameters} numbers.";
            }
        }
        return hasCode ? null : "there is no instruction code.";
    }

    private static string Short(string token) => token.Length <= 20 ? token : token[..17] + "...";
}
