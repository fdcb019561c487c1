using System.Text.RegularExpressions;

namespace Machina.Tests.Brands.Registry;

/// <summary>
/// Finds where a C# source names a brand (docs/architecture.md, "Brands"). Two rules:
/// (1) a string literal whose whole text, trimmed and in any letter case, is a brand's name or alias of <see cref="BrandRegistry"/>
/// ("abb", "UR", "universal robots"…), except "Machina" written exactly so, which is the library's own name (a robot's default name,
/// a log prefix), not the MACHINA listing brand; raw string literals (help texts) and whole-line comments are not read, and a name inside a
/// longer text ("only ABB, UR and KUKA robots can") is prose, not a brand chosen in code;
/// (2) with <c>members</c>, a <c>RobotType.X</c> member (a decision taken for one brand).
/// </summary>
internal static partial class BrandNameScanner
{
    /// <summary>The library's name, which is not the MACHINA brand when written exactly so.</summary>
    private const string ProductName = "Machina";

    /// <summary>Every brand name and alias, in lower case.</summary>
    internal static HashSet<string> Names() =>
        [.. BrandRegistry.All.SelectMany(b => b.Aliases.Append(b.Name).Append(b.DisplayName)).Select(n => n.ToLowerInvariant())];

    /// <summary>The brand names <paramref name="source"/> holds, as "line N: text" (the literal with its quotes, or RobotType.X).</summary>
    internal static List<string> Find(string source, bool members)
    {
        HashSet<string> names = Names();
        var found = new List<string>();
        // Blank raw literals and whole-line comments, keeping the line breaks so that line numbers stay right.
        string text = RawLiteral().Replace(source, m => new string('\n', m.Value.Count(c => c == '\n')));
        text = LineComment().Replace(text, "");
        string[] lines = text.Split('\n');
        for (int i = 0; i < lines.Length; i++)
        {
            foreach (Match m in Literal().Matches(lines[i]))
            {
                string literal = m.Groups["text"].Value.Trim();
                if (names.Contains(literal.ToLowerInvariant()) && literal != ProductName)
                {
                    found.Add($"line {i + 1}: {m.Value}");
                }
            }
            if (members)
            {
                foreach (Match m in Member().Matches(lines[i]))
                {
                    found.Add($"line {i + 1}: {m.Value}");
                }
            }
        }
        return found;
    }

    [GeneratedRegex("\"\"\"[\\s\\S]*?\"\"\"")]
    private static partial Regex RawLiteral();

    [GeneratedRegex(@"^[ \t]*//.*$", RegexOptions.Multiline)]
    private static partial Regex LineComment();

    [GeneratedRegex("\\$?@?\"(?<text>(?:[^\"\\\\]|\\\\.)*)\"")]
    private static partial Regex Literal();

    [GeneratedRegex(@"\bRobotType\.(?:HUMAN|MACHINA|ABB|UR|KUKA|ZMORPH|MARLIN)\b")]
    private static partial Regex Member();
}
