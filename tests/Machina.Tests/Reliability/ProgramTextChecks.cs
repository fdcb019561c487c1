namespace Machina.Tests.Reliability;

/// <summary>What no compiled program may contain, whatever was issued: numbers that are not numbers, strings left open, line breaks inside a line.</summary>
internal static class ProgramTextChecks
{
    private static readonly string[] NotNumbers = ["NaN", "Infinity", "∞"];

    /// <summary>The first problem of a compiled program's lines, or null.</summary>
    internal static string? Problem(RobotType language, IReadOnlyList<string> lines)
    {
        for (int i = 0; i < lines.Count; i++)
        {
            string line = lines[i];
            if (NotNumbers.FirstOrDefault(n => line.Contains(n, StringComparison.Ordinal)) is string n)
            {
                return $"line {i + 1} contains {n}: {Shorten(line)}";
            }
            ReadOnlySpan<char> span = line;
            if (span.IndexOfAnyInRange('\0', '\u0008') >= 0 || span.IndexOfAnyInRange('\n', '\u001f') >= 0 || span.IndexOfAnyInRange('\u007f', '\u009f') >= 0
                || span.IndexOfAny('\u2028', '\u2029') >= 0)
            {
                return $"line {i + 1} contains a control character: {Shorten(line)}";
            }
            if (OpenString(language, line))
            {
                return $"line {i + 1} leaves a string open: {Shorten(line)}";
            }
        }
        if (language == RobotType.MACHINA)
        {
            try
            {
                Instructions.Parse(string.Join("\n", lines));
            }
            catch (InstructionParseException e)
            {
                return $"the Machina program does not read back: {e.Message}";
            }
        }
        return null;
    }

    /// <summary>True when a string literal is still open at the end of the line (comments skipped, each language's escapes honoured).</summary>
    private static bool OpenString(RobotType language, string line)
    {
        char comment = language switch
        {
            RobotType.ABB => '!',
            RobotType.UR => '#',
            RobotType.KUKA => ';',
            _ => '\0',
        };
        if (comment == '\0')
        {
            return false; // G-code has no strings; the human listing is prose; Machina is read back instead
        }
        if (!line.Contains('"', StringComparison.Ordinal))
        {
            return false;
        }
        bool inString = false;
        for (int i = 0; i < line.Length; i++)
        {
            char c = line[i];
            if (!inString)
            {
                if (c == comment)
                {
                    return false;
                }
                inString = c == '"';
            }
            else if (language == RobotType.ABB && (c == '\\' || c == '"') && i + 1 < line.Length && line[i + 1] == c)
            {
                i++; // RAPID doubles quotes and backslashes
            }
            else if (c == '"')
            {
                inString = false;
            }
        }
        return inString;
    }

    internal static string Shorten(string text) => text.Length <= 160 ? text : text[..160] + $"… ({text.Length} characters)";
}
