using System.Text.RegularExpressions;
using Machina.Tests.Conventions;

namespace Machina.Tests.Docs;

/// <summary>
/// Reads the documentation the way the doc tests check it: `###` sections of a markdown page, fenced code blocks, regions
/// written by a test (<c>&lt;!-- generated: kind --&gt;</c> … <c>&lt;!-- /generated --&gt;</c>), and the method bodies of a C#
/// file that hold the page's examples. With MACHINA_UPDATE_DOCS=1 the tests rewrite the generated regions instead of failing.
/// </summary>
internal static partial class DocText
{
    /// <summary>True when the tests should rewrite generated regions (MACHINA_UPDATE_DOCS=1) instead of comparing them.</summary>
    internal static bool Updating => Environment.GetEnvironmentVariable("MACHINA_UPDATE_DOCS") == "1";

    /// <summary>The full path of a file of the repository, e.g. "docs/reference.md".</summary>
    internal static string PathOf(string relative) => Path.Combine(ConventionTests.RepositoryRoot(), relative);

    /// <summary>The lines of a file of the repository (LF line ends).</summary>
    internal static List<string> ReadLines(string relative) => [.. File.ReadAllText(PathOf(relative)).Replace("\r\n", "\n").TrimEnd('\n').Split('\n')];

    /// <summary>
    /// The bodies of the methods of a C# source file, by method name, without their braces and dedented to the left
    /// margin (the file must indent method bodies by 8 spaces, as the house style does).
    /// </summary>
    internal static Dictionary<string, string> MethodBodies(string relativeSource)
    {
        string source = File.ReadAllText(PathOf(relativeSource)).Replace("\r\n", "\n");
        var bodies = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (Match m in MethodRegex().Matches(source))
        {
            IEnumerable<string> lines = m.Groups["body"].Value.Split('\n').Select(l => l.Length >= 8 ? l[8..] : l.TrimStart());
            bodies.Add(m.Groups["name"].Value, string.Join("\n", lines));
        }
        return bodies;
    }

    [GeneratedRegex(@"^    internal static (?:async )?[\w<>?]+ (?<name>\w+)\([^)]*\)\n    \{\n(?<body>.*?)\n    \}$", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex MethodRegex();

    /// <summary>The `###` sections of a page: heading line, the names in backticks in the heading, and the section's line range.</summary>
    internal static List<DocSection> Sections(IReadOnlyList<string> lines)
    {
        var sections = new List<DocSection>();
        int? start = null;
        for (int i = 0; i <= lines.Count; i++)
        {
            bool boundary = i == lines.Count || lines[i].StartsWith("## ", StringComparison.Ordinal) || lines[i].StartsWith("### ", StringComparison.Ordinal);
            if (!boundary)
            {
                continue;
            }
            if (start is int s)
            {
                string[] names = [.. HeadingNameRegex().Matches(lines[s]).Select(m => m.Groups[1].Value)];
                sections.Add(new DocSection(lines[s], names, s, i));
            }
            start = i < lines.Count && lines[i].StartsWith("### ", StringComparison.Ordinal) ? i : null;
        }
        return sections;
    }

    [GeneratedRegex(@"`(\w+)`")]
    private static partial Regex HeadingNameRegex();

    /// <summary>The content of the first fenced block of <paramref name="language"/> in a line range, outside generated regions, or null.</summary>
    internal static string? FirstFence(IReadOnlyList<string> lines, int start, int end, string language)
    {
        bool generated = false;
        for (int i = start; i < end; i++)
        {
            if (lines[i].StartsWith("<!-- generated:", StringComparison.Ordinal))
            {
                generated = true;
            }
            else if (lines[i] == "<!-- /generated -->")
            {
                generated = false;
            }
            else if (!generated && lines[i] == "```" + language)
            {
                int close = i + 1;
                while (close < end && lines[close] != "```")
                {
                    close++;
                }
                return string.Join("\n", lines.Skip(i + 1).Take(close - i - 1));
            }
        }
        return null;
    }

    /// <summary>The fenced block that follows the marker line <c>&lt;!-- checked: name --&gt;</c>, by name, for every marker in a page.</summary>
    internal static Dictionary<string, string> CheckedFences(IReadOnlyList<string> lines)
    {
        var fences = new Dictionary<string, string>(StringComparer.Ordinal);
        for (int i = 0; i < lines.Count; i++)
        {
            if (CheckedRegex().Match(lines[i]) is { Success: true } m)
            {
                int open = i + 1;
                int close = open + 1;
                while (close < lines.Count && lines[close] != "```")
                {
                    close++;
                }
                if (open >= lines.Count || !lines[open].StartsWith("```", StringComparison.Ordinal) || close >= lines.Count)
                {
                    throw new InvalidOperationException($"The marker on line {i + 1} is not followed by a fenced block.");
                }
                fences.Add(m.Groups[1].Value, string.Join("\n", lines.Skip(open + 1).Take(close - open - 1)));
            }
        }
        return fences;
    }

    [GeneratedRegex(@"^<!-- checked: (\w+) -->$")]
    private static partial Regex CheckedRegex();

    /// <summary>
    /// The generated region of <paramref name="kind"/> in a section (start and end marker lines), or null when the section has none.
    /// </summary>
    internal static (int Open, int Close)? Region(IReadOnlyList<string> lines, DocSection section, string kind)
    {
        for (int i = section.Start; i < section.End; i++)
        {
            if (lines[i] == $"<!-- generated: {kind} -->")
            {
                for (int j = i + 1; j < section.End; j++)
                {
                    if (lines[j] == "<!-- /generated -->")
                    {
                        return (i, j);
                    }
                }
                throw new InvalidOperationException($"The generated region on line {i + 1} has no end marker.");
            }
        }
        return null;
    }
}

/// <summary>A `###` section of a page: its heading, the backticked names in it, and its lines [Start, End).</summary>
internal sealed record DocSection(string Heading, string[] Names, int Start, int End);
