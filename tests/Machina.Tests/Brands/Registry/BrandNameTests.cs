using Machina.Tests.Conventions;

namespace Machina.Tests.Brands.Registry;

/// <summary>
/// One list of brands (issue 21 §3): outside a brand's folder (src/Machina/Brands/) and the virtual-controller registry, nothing in
/// src/ or samples/ names a brand as a string literal, and nothing in src/ takes a decision with a <c>RobotType.X</c> member (samples
/// may: they are user code, choosing a brand as a user does). See <see cref="BrandNameScanner"/> for the precise rule.
/// </summary>
public sealed class BrandNameTests
{
    /// <summary>Where a brand's name may stand outside the registry, and why (keep it short).</summary>
    private static readonly (string File, string Text, string Why)[] Allowed =
    [
        ("samples/HelloRobot/HelloRobotSample.cs", "\"ABB\"", "shows Robot.Create with the brand as text, the way a user writes it"),
    ];

    private static readonly string[] Exempt =
    [
        "src/Machina/Brands/",
        "src/Machina.Simulation/VirtualControllerRegistry.cs",
    ];

    [Fact]
    public void NoBrandIsNamedOutsideItsFolderAndTheRegistries()
    {
        string root = ConventionTests.RepositoryRoot();
        var offences = new List<string>();
        foreach (string folder in new[] { "src", "samples" })
        {
            foreach (string path in Directory.EnumerateFiles(Path.Combine(root, folder), "*.cs", SearchOption.AllDirectories))
            {
                string relative = Path.GetRelativePath(root, path).Replace('\\', '/');
                if (relative.Contains("/obj/", StringComparison.Ordinal) || relative.Contains("/bin/", StringComparison.Ordinal)
                    || Exempt.Any(e => relative.StartsWith(e, StringComparison.Ordinal)))
                {
                    continue;
                }
                foreach (string hit in BrandNameScanner.Find(File.ReadAllText(path), members: folder == "src"))
                {
                    if (!Allowed.Any(a => a.File == relative && hit.EndsWith(a.Text, StringComparison.Ordinal)))
                    {
                        offences.Add($"{relative} {hit}");
                    }
                }
            }
        }

        Assert.True(offences.Count == 0, "Brands named outside src/Machina/Brands/ (read them from BrandRegistry instead):\n" + string.Join("\n", offences));
    }

    [Fact]
    public void Scanner_FindsLiteralsAndMembers_NotProseCommentsOrHelpTexts()
    {
        string source = string.Join('\n',
            "// \"abb\" in a comment",
            "string a = \"ABB\";",
            "string b = $\" kuka \";",
            "string c = \"only ABB, UR and KUKA robots can\";",
            "string d = \"\"\"",
            "    ur",
            "    \"\"\";",
            "if (brand == RobotType.UR && x is \"Universal Robots\") { }",
            "string e = \"UR5e\";",
            "string f = \"Machina\" + \"MACHINA\";");

        Assert.Equal(["line 2: \"ABB\"", "line 3: $\" kuka \"", "line 8: \"Universal Robots\"", "line 8: RobotType.UR", "line 10: \"MACHINA\""], BrandNameScanner.Find(source, members: true));
        Assert.Equal(["line 2: \"ABB\"", "line 3: $\" kuka \"", "line 8: \"Universal Robots\"", "line 10: \"MACHINA\""], BrandNameScanner.Find(source, members: false));
    }
}
