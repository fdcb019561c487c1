using System.Reflection;

namespace Machina.Tests.Docs;

/// <summary>
/// docs/reference.md cannot drift from the code: every public member of <see cref="Robot"/> has a `###` section, every
/// section shows the member's real signatures, every action verb's example is the code of <see cref="ReferenceExamples"/>,
/// and the native lines under it are what the compilers and the online encoders produce. Run with MACHINA_UPDATE_DOCS=1 to
/// rewrite the generated parts after a deliberate change, then read the diff.
/// </summary>
public class ReferenceDocTests
{
    private const string Page = "docs/reference.md";

    [Fact]
    public void Reference_EveryPublicMemberOfRobot_HasASection()
    {
        var documented = DocText.Sections(DocText.ReadLines(Page)).SelectMany(s => s.Names).ToHashSet(StringComparer.Ordinal);

        string[] missing = [.. ReferenceGenerator.PublicMemberNames().Where(n => !documented.Contains(n))];

        Assert.True(missing.Length == 0,
            $"{Page} has no section for these public members of Robot: {string.Join(", ", missing)}. Add a \"### `Name`\" section for each.");
    }

    [Fact]
    public void Reference_EverySectionName_IsAPublicMemberOfRobot()
    {
        SortedSet<string> members = ReferenceGenerator.PublicMemberNames();

        string[] stale = [.. DocText.Sections(DocText.ReadLines(Page)).SelectMany(s => s.Names).Where(n => !members.Contains(n))];

        Assert.True(stale.Length == 0, $"{Page} has sections for names Robot does not have (renamed or removed?): {string.Join(", ", stale)}.");
    }

    [Fact]
    public void Reference_EveryActionVerb_HasItsOwnSectionWithAnExampleThatIsTheTestedCode()
    {
        List<string> lines = DocText.ReadLines(Page);
        var sections = DocText.Sections(lines);
        Dictionary<string, string> examples = DocText.MethodBodies("tests/Machina.Tests/Docs/ReferenceExamples.cs");
        var problems = new List<string>();

        foreach (string verb in ReferenceGenerator.ActionVerbs())
        {
            DocSection? section = sections.FirstOrDefault(s => s.Names is [var only] && only == verb);
            if (section is null)
            {
                problems.Add($"{verb}: no section of its own (\"### `{verb}`\")");
                continue;
            }
            if (!examples.TryGetValue(verb, out string? code))
            {
                problems.Add($"{verb}: no example method ReferenceExamples.{verb}");
                continue;
            }
            string? shown = DocText.FirstFence(lines, section.Start, section.End, "csharp");
            if (shown != code)
            {
                problems.Add($"{verb}: the example shown is\n{shown}\nbut the tested example is\n{code}");
            }
        }

        Assert.True(problems.Count == 0, string.Join("\n\n", problems));
    }

    [Fact]
    public void Reference_Signatures_AreTheRealOnes()
    {
        Check("signatures", section => section.Names.Length == 0 ? null : ReferenceGenerator.Signatures(section.Names));
    }

    [Fact]
    public void Reference_NativeLines_AreWhatTheCompilersAndEncodersProduce()
    {
        Check("native", section =>
        {
            if (section.Names is not [var verb] || !ReferenceGenerator.ActionVerbs().Contains(verb))
            {
                return null;
            }
            MethodInfo example = typeof(ReferenceExamples).GetMethod(verb, BindingFlags.NonPublic | BindingFlags.Static)
                ?? throw new InvalidOperationException($"No example method ReferenceExamples.{verb}.");
            return ReferenceGenerator.NativeTable(bot => example.Invoke(null, [bot]));
        });
    }

    [Fact]
    public void Added_LineEqualToTheProgramsClosingOne_CountsWhereItStands()
    {
        // A UR wait loop's "end" before an unsupported line, then the program's own "end": the loop keeps its "end".
        string[] before = ["def p():", "movel(a)", "end"];
        string[] after = ["def p():", "movel(a)", "while x:", "sync()", "end", "# NOT SUPPORTED", "end"];

        Assert.Equal(["while x:", "sync()", "end", "# NOT SUPPORTED"], ReferenceGenerator.Added(before, after));
        Assert.Equal(["b"], ReferenceGenerator.Added(["a", "c"], ["a", "b", "c"]));
        Assert.Empty(ReferenceGenerator.Added(["a", "b"], ["a", "b"]));
    }

    [Fact]
    public void NativeTable_MoveTo_HasTheExactLinesOfEachBrand()
    {
        // The generator itself must be able to fail: a known example gives known lines (values checked by hand against
        // the golden files and docs/protocol-abb.md, docs/protocol-ur.md).
        List<string> table = ReferenceGenerator.NativeTable(bot => bot.MoveTo(300, 200, 400));

        Assert.Equal("| ABB | `MoveL [[300, 200, 400], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel20, z5, Tool0\\WObj:=WObj0;` | `@2 1 300 200 400 0 0 1 0;` |", table[2]);
        Assert.Equal("| UR | `movep(p[0.3,0.2,0.4,0,3.141593,0], v=0.02, r=0.005)` | `2 1 300000 200000 400000 0 3141593 0` |", table[3]);
        Assert.Equal("| Marlin | `G0 X300 Y200 Z400` | no online control |", table[6]);
    }

    /// <summary>
    /// Compares (or, when updating, rewrites) every generated region of <paramref name="kind"/>: each section for which
    /// <paramref name="generate"/> returns lines must hold exactly those lines in its region.
    /// </summary>
    private static void Check(string kind, Func<DocSection, List<string>?> generate)
    {
        List<string> lines = DocText.ReadLines(Page);
        var problems = new List<string>();
        // From the last section up, so that rewriting a region does not move the ones still to visit.
        foreach (DocSection section in DocText.Sections(lines).AsEnumerable().Reverse())
        {
            if (generate(section) is not List<string> expected)
            {
                continue;
            }
            if (DocText.Region(lines, section, kind) is not (int open, int close))
            {
                problems.Add($"{section.Heading}: no \"<!-- generated: {kind} -->\" region");
                continue;
            }
            List<string> actual = lines.GetRange(open + 1, close - open - 1);
            if (!actual.SequenceEqual(expected))
            {
                problems.Add($"{section.Heading}: the {kind} should be\n{string.Join("\n", expected)}\nbut the page has\n{string.Join("\n", actual)}");
                lines.RemoveRange(open + 1, close - open - 1);
                lines.InsertRange(open + 1, expected);
            }
        }
        if (DocText.Updating && problems.Count > 0)
        {
            File.WriteAllText(DocText.PathOf(Page), string.Join("\n", lines) + "\n");
            return;
        }
        Assert.True(problems.Count == 0, $"{Page} differs from the code (MACHINA_UPDATE_DOCS=1 rewrites it):\n\n" + string.Join("\n\n", problems));
    }
}
