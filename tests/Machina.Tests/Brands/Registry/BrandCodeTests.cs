using System.Text;
using System.Text.RegularExpressions;
using Machina.Tests.Conventions;

namespace Machina.Tests.Brands.Registry;

/// <summary>
/// A brand lives in its folder (src/Machina/Brands/NAME) and the registries (docs/architecture.md, "Brands"): no other code of the
/// library, the command line or the bridge names one, in an identifier (AbbDriverInstaller, GCodeArc, UrBrand, VirtualAbbController)
/// or anywhere in a string, except the few files listed here with their reason. Comments may name brands, and so may the command
/// line's help texts (its raw string literals: prose for a person). The command line's <c>Twins/</c> folder is its registry of twins,
/// one class per brand. (<see cref="BrandNameTests"/> checks the whole tree for brand names chosen as text and RobotType members;
/// this checks the code for any brand's types and names.)
/// </summary>
public partial class BrandCodeTests
{
    /// <summary>The files outside Brands/ that may name a brand, each with why (paths under src/Machina).</summary>
    private static readonly Dictionary<string, string> Exceptions = new(StringComparer.Ordinal)
    {
        ["Enums/RobotType.cs"] = "the public enum of brands (the original API's names), which the registry is keyed on",
        ["Kinematics/KinematicFamily.cs"] = "public API: the Universal Robots joint layout is a kinematic family of its own",
        ["Kinematics/RobotModel.cs"] = "public API: RobotModel.UniversalRobotsDh and FromUniversalRobotsDh, and the OPW joint conventions' names",
        ["Robot.Connection.cs"] = "the text of ConnectionManager(\"machina\")'s refusal, which tells what to do on each brand (docs/migrating.md links it)",
        ["State/RobotCursor.Apply.cs"] = "the refusal of an external axis value names where the 9E9 'no axis' value comes from (ABB's)",
    };

    /// <summary>The files of the command line and the bridge that may name a brand in code (paths under src/), each with why.</summary>
    private static readonly Dictionary<string, string> HostExceptions = new(StringComparer.Ordinal)
    {
        ["Machina.Cli/Commands/ModelsCommand.cs"] = "prints the Universal Robots parameters of a model (public API: RobotModel.UniversalRobotsDh)",
        ["Machina.Cli/Commands/VerifyCommand.cs"] = "the command's one-line summary in the help list names the brands it verifies",
    };

    [Fact]
    public void BrandNames_AppearOnlyInTheBrandFoldersAndTheRegistries()
    {
        string root = Path.Combine(ConventionTests.RepositoryRoot(), "src", "Machina");
        var found = new List<string>();
        foreach (string file in LibraryFiles(root))
        {
            string relative = Path.GetRelativePath(root, file).Replace('\\', '/');
            if (!Exceptions.ContainsKey(relative))
            {
                found.AddRange(Hits(File.ReadAllText(file)).Select(h => $"{relative}:{h.Line} {h.Name}"));
            }
        }
        Assert.True(found.Count == 0, "A brand is named outside src/Machina/Brands (move the code into the brand's folder, reach it through " +
            "BrandDefinition, or add the file to Exceptions with a reason):\n" + string.Join("\n", found));
    }

    [Fact]
    public void BrandNames_AppearInTheCommandLineAndBridgeOnlyThroughTheRegistries()
    {
        string src = Path.Combine(ConventionTests.RepositoryRoot(), "src");
        var found = new List<string>();
        foreach (string file in HostFiles(src))
        {
            string relative = Path.GetRelativePath(src, file).Replace('\\', '/');
            if (!HostExceptions.ContainsKey(relative))
            {
                found.AddRange(Hits(File.ReadAllText(file), helpTexts: true).Select(h => $"{relative}:{h.Line} {h.Name}"));
            }
        }
        Assert.True(found.Count == 0, "A brand is named in the command line's or the bridge's code (read what differs from BrandRegistry or " +
            "VirtualControllerRegistry, put a brand's twin under Machina.Cli/Twins, or add the file to HostExceptions with a reason):\n" +
            string.Join("\n", found));
    }

    [Fact]
    public void EveryException_StillNamesABrand()
    {
        string src = Path.Combine(ConventionTests.RepositoryRoot(), "src");
        foreach ((string relative, bool helpTexts) in Exceptions.Keys.Select(k => ("Machina/" + k, false)).Concat(HostExceptions.Keys.Select(k => (k, true))))
        {
            string file = Path.Combine(src, relative);
            Assert.True(File.Exists(file), $"{relative} is listed as an exception but does not exist: remove it from the list.");
            Assert.True(Hits(File.ReadAllText(file), helpTexts).Count > 0, $"{relative} no longer names a brand: remove it from the list.");
        }
    }

    [Fact]
    public void Hits_FindBrandsInCodeAndStrings_NotInComments()
    {
        const string code = """
            // ABB in a comment, and Rapid too
            /// <summary>KUKA in documentation.</summary>
            /* UR in a block comment */
            var url = "https://example.com"; // a Kuka comment after code
            var compiler = new RapidCompiler();
            string s = "on a UR5e";
            bool b = brand == RobotType.KUKA;
            bool q = c != '"'; // "a quote in a character literal opens no string: Rapid"
            var arc = GCodeArc.Create(); var bytes = "URL, URI and Urgent are no brands";
            """;
        Assert.Equal([(5, "Rapid"), (6, "UR"), (7, "KUKA"), (9, "GCode")], Hits(code));
    }

    [Fact]
    public void Hits_WithHelpTexts_SkipRawStringsOnly()
    {
        const string code = "string help = \"\"\"\n  --brand abb|ur  the ABB or UR controller\n  \"\"\";\n" +
            "string summary = \"Run a UR program\";\nbool b = c is VirtualAbbController;\n";
        Assert.Equal([(2, "ABB"), (4, "UR"), (5, "Abb")], Hits(code));
        Assert.Equal([(4, "UR"), (5, "Abb")], Hits(code, helpTexts: true));
    }

    /// <summary>Every .cs file of the library outside Brands/ (and the build's own folders).</summary>
    private static IEnumerable<string> LibraryFiles(string root) =>
        Directory.EnumerateFiles(root, "*.cs", SearchOption.AllDirectories)
            .Where(f => Path.GetRelativePath(root, f).Replace('\\', '/').Split('/')[0] is not ("Brands" or "bin" or "obj"))
            .Order(StringComparer.Ordinal);

    /// <summary>Every .cs file of the command line (outside its Twins/ folder) and the bridge (and not the build's own folders).</summary>
    private static IEnumerable<string> HostFiles(string src) =>
        new[] { "Machina.Cli", "Machina.Bridge" }.SelectMany(p => Directory.EnumerateFiles(Path.Combine(src, p), "*.cs", SearchOption.AllDirectories))
            .Where(f => Path.GetRelativePath(src, f).Replace('\\', '/').Split('/')[1] is not ("Twins" or "bin" or "obj"))
            .Order(StringComparer.Ordinal);

    /// <summary>
    /// Each line (1-based) of <paramref name="source"/>'s code and strings that names a brand, with the first name on it; with
    /// <paramref name="helpTexts"/>, not in raw string literals (the command line's help texts).
    /// </summary>
    internal static List<(int Line, string Name)> Hits(string source, bool helpTexts = false)
    {
        string[] lines = WithoutComments(source, helpTexts).Split('\n');
        var hits = new List<(int, string)>();
        for (int i = 0; i < lines.Length; i++)
        {
            if (BrandName().Match(lines[i]) is { Success: true } m)
            {
                hits.Add((i + 1, m.Value));
            }
        }
        return hits;
    }

    /// <summary>
    /// The source with its comments blanked out (line breaks kept, so lines keep their numbers); string literals are kept, but for raw
    /// ones when <paramref name="rawStrings"/> blanks them too.
    /// </summary>
    private static string WithoutComments(string s, bool rawStrings = false)
    {
        var text = new StringBuilder(s.Length);
        int i = 0;
        while (i < s.Length)
        {
            if (s[i] == '"')
            {
                int end = StringEnd(s, i);
                bool raw = end - i >= 6 && string.CompareOrdinal(s, i, "\"\"\"", 0, 3) == 0;
                if (raw && rawStrings)
                {
                    text.Append(s[i..end].Where(c => c == '\n').ToArray());
                }
                else
                {
                    text.Append(s, i, end - i);
                }
                i = end;
            }
            else if (s[i] == '\'' && i + 2 < s.Length)
            {
                // A character literal ('"', '\'', 'x'): its quote is no string's.
                int end = s[i + 1] == '\\' ? s.IndexOf('\'', i + 3) + 1 : i + 3;
                end = end <= 0 ? s.Length : end;
                text.Append(s, i, end - i);
                i = end;
            }
            else if (s[i] == '/' && i + 1 < s.Length && (s[i + 1] == '/' || s[i + 1] == '*'))
            {
                int end = s[i + 1] == '/' ? s.IndexOf('\n', i) : s.IndexOf("*/", i + 2, StringComparison.Ordinal) + 2;
                end = end <= 1 ? s.Length : end;
                text.Append(s[i..end].Where(c => c == '\n').ToArray());
                i = end;
            }
            else
            {
                text.Append(s[i++]);
            }
        }
        return text.ToString();
    }

    /// <summary>The index after the string literal starting at <paramref name="start"/> (a regular, verbatim or raw one; an interpolated one's holes are read as text).</summary>
    private static int StringEnd(string s, int start)
    {
        bool verbatim = start > 0 && (s[start - 1] == '@' || (start > 1 && s[start - 2] == '@'));
        int quotes = 0;
        while (start + quotes < s.Length && s[start + quotes] == '"')
        {
            quotes++;
        }
        if (quotes >= 3)
        {
            int close = s.IndexOf(new string('"', quotes), start + quotes, StringComparison.Ordinal);
            return close < 0 ? s.Length : close + quotes;
        }
        if (quotes == 2)
        {
            return start + 2; // ""
        }
        for (int i = start + 1; i < s.Length; i++)
        {
            if (!verbatim && s[i] == '\\')
            {
                i++;
            }
            else if (s[i] == '"')
            {
                if (verbatim && i + 1 < s.Length && s[i + 1] == '"')
                {
                    i++;
                    continue;
                }
                return i + 1;
            }
            else if (s[i] == '\n' && !verbatim)
            {
                return i;
            }
        }
        return s.Length;
    }

    // The brands' names as code writes them: ABB, KUKA, UR (not URL or URI), Universal Robots, the G-code printers, and the names of
    // their languages and types (Abb…, Kuka…, Ur…, GCode…, Rapid…, Krl…, UrScript…).
    [GeneratedRegex(@"\b(?:ABB|KUKA|UR)(?![A-Za-z])|Abb|Kuka|Universal|GCode|Gcode|Rapid|Krl|UrScript|\bUr(?=[A-Z])|Marlin|ZMorph")]
    private static partial Regex BrandName();
}
