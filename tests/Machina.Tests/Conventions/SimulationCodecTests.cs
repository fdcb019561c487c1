using System.Text.RegularExpressions;

namespace Machina.Tests.Conventions;

/// <summary>
/// The virtual controllers must learn a brand's wire by running its driver, not by borrowing the host's codecs (issue 26): no
/// file of src/Machina.Simulation may use an internal type declared under src/Machina/Brands (the host's encoders, readers,
/// message formats). Public types (geometry, kinematics, what any user may call) are allowed. The mirrors that still imitate a
/// driver are listed below with what they use; the list may only shrink. The brand definitions (BrandRegistry, AbbBrand…) are
/// not codecs: the virtual-controller registry reads a brand's name and default model from them.
/// </summary>
public class SimulationCodecTests
{
    /// <summary>File → host types it still uses. Remove entries as the imitations are replaced; never add one.</summary>
    private static readonly Dictionary<string, string[]> AllowList = new(StringComparer.Ordinal)
    {
    };

    private static readonly Regex Declaration = new(
        @"^(?:(public|internal)\s+)?(?:(?:sealed|static|abstract|readonly|partial|ref)\s+)*(?:class|struct|record struct|record|enum|interface)\s+([A-Z][A-Za-z0-9_]*)",
        RegexOptions.Multiline | RegexOptions.CultureInvariant);

    [Fact]
    public void Simulation_UsesNoInternalHostCodecOfBrands_ExceptTheShrinkingAllowList()
    {
        string root = ConventionTests.RepositoryRoot();
        var hostTypes = new SortedSet<string>(StringComparer.Ordinal);
        foreach (string file in Directory.EnumerateFiles(Path.Combine(root, "src/Machina/Brands"), "*.cs", SearchOption.AllDirectories))
        {
            string name = Path.GetFileName(file);
            if (name.StartsWith("Brand", StringComparison.Ordinal) || name.EndsWith("Brand.cs", StringComparison.Ordinal))
            {
                continue; // a brand's definition (name, default model, ports) says who the brand is, not how its wire reads
            }
            foreach (Match m in Declaration.Matches(File.ReadAllText(file)))
            {
                if (m.Groups[1].Value != "public")
                {
                    hostTypes.Add(m.Groups[2].Value);
                }
            }
        }
        Assert.Contains("UrWire", hostTypes); // the scan sees the host's codecs
        Assert.Contains("KukaXmlReader", hostTypes);

        var found = new Dictionary<string, string[]>(StringComparer.Ordinal);
        foreach (string file in Directory.EnumerateFiles(Path.Combine(root, "src/Machina.Simulation"), "*.cs", SearchOption.AllDirectories))
        {
            if (file.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal))
            {
                continue;
            }
            string code = string.Join('\n', File.ReadLines(file).Select(l => l.TrimStart().StartsWith("//", StringComparison.Ordinal) ? "" : l));
            string[] used = [.. hostTypes.Where(t => Regex.IsMatch(code, $@"(?<![\w.]){t}\b"))];
            if (used.Length > 0)
            {
                found[Path.GetRelativePath(Path.Combine(root, "src/Machina.Simulation"), file).Replace('\\', '/')] = used;
            }
        }

        var problems = new List<string>();
        foreach ((string file, string[] used) in found)
        {
            string[] allowed = AllowList.GetValueOrDefault(file, []);
            foreach (string type in used.Except(allowed))
            {
                problems.Add($"{file} uses the host's {type}: a virtual controller learns the wire by running the driver.");
            }
        }
        foreach ((string file, string[] allowed) in AllowList)
        {
            foreach (string type in allowed.Except(found.GetValueOrDefault(file, [])))
            {
                problems.Add($"{file} no longer uses {type}: remove it from the allow-list.");
            }
        }
        Assert.True(problems.Count == 0, string.Join("\n", problems));
        Assert.DoesNotContain(found.Keys, f => f.StartsWith("UrScript/", StringComparison.Ordinal) || f.StartsWith("Twin/", StringComparison.Ordinal) || f.Contains("Twin", StringComparison.Ordinal));
    }
}
