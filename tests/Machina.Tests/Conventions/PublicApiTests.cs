using System.Reflection;
using Machina.Simulation;

namespace Machina.Tests.Conventions;

/// <summary>
/// The public surface of each library is checked in (src/&lt;Library&gt;/PublicAPI.txt), so that every change to it shows up as a
/// diff in review. When a test fails it writes PublicAPI.actual.txt next to the checked-in file (git-ignored): if the change
/// is intended, copy it over PublicAPI.txt.
/// </summary>
public class PublicApiTests
{
    internal const string Header =
        "# The public API of {0}: one line per public type and member, produced by tests/Machina.Tests/Conventions/PublicApiTests.cs.\n" +
        "# When the API changes on purpose, the test writes PublicAPI.actual.txt next to this file: copy it over this one.\n";

    [Fact]
    public void PublicApi_Machina_MatchesCheckedInListing() => AssertMatches(typeof(Robot).Assembly, "src/Machina");

    [Fact]
    public void PublicApi_MachinaSimulation_MatchesCheckedInListing() => AssertMatches(typeof(VirtualAbbController).Assembly, "src/Machina.Simulation");

    [Fact]
    public void Describe_Vector_ListsConstructorOperatorsAndPropertiesInOneLineEach()
    {
        var lines = PublicApiListing.Describe(typeof(Robot).Assembly);

        Assert.Contains("readonly struct Machina.Vector : System.IEquatable<Machina.Vector>", lines);
        Assert.Contains("Machina.Vector.Vector(double X, double Y, double Z)", lines);
        Assert.Contains("Machina.Vector.X { get; init; } -> double", lines);
        Assert.Contains("static Machina.Vector.operator +(Machina.Vector a, Machina.Vector b) -> Machina.Vector", lines);
        Assert.Contains("Machina.Vector.DistanceTo(Machina.Vector other) -> double", lines);
    }

    [Fact]
    public void Describe_NullableReferenceAndConstant_AreSpelledOut()
    {
        var lines = PublicApiListing.Describe(typeof(Robot).Assembly);
        var bare = PublicApiListing.Describe(typeof(Robot).Assembly, annotations: false);

        Assert.Contains("Machina.ExternalAxes.Count (const = 6) -> int", lines);
        Assert.Contains(lines, l => l.StartsWith("event Machina.Robot.ActionIssued -> Machina.Robot.ActionIssuedHandler?", StringComparison.Ordinal));
        Assert.Contains(bare, l => l.StartsWith("event Machina.Robot.ActionIssued -> Machina.Robot.ActionIssuedHandler", StringComparison.Ordinal)
            && !l.EndsWith('?'));
    }

    [Fact]
    public void Describe_SameAssemblyTwice_GivesTheSameSortedLines()
    {
        var first = PublicApiListing.Describe(typeof(Robot).Assembly);
        var second = PublicApiListing.Describe(typeof(Robot).Assembly);

        Assert.Equal(first, second);
        Assert.True(first.Count > 500, $"only {first.Count} lines");
    }

    private static void AssertMatches(Assembly assembly, string projectFolder)
    {
        string folder = Path.Combine(ConventionTests.RepositoryRoot(), projectFolder);
        string expectedPath = Path.Combine(folder, "PublicAPI.txt");
        string actualPath = Path.Combine(folder, "PublicAPI.actual.txt");
        var actual = PublicApiListing.Describe(assembly);
        var expected = File.Exists(expectedPath) ? PublicApiListing.Parse(File.ReadAllText(expectedPath)) : [];

        string diff = Diff(expected, actual);
        if (diff.Length == 0)
        {
            return;
        }
        File.WriteAllText(actualPath, string.Format(System.Globalization.CultureInfo.InvariantCulture, Header, assembly.GetName().Name) + PublicApiListing.ToText(actual));
        Assert.Fail($"The public API of {assembly.GetName().Name} differs from {projectFolder}/PublicAPI.txt " +
            $"(- only in the file, + only in the build). If intended, copy {projectFolder}/PublicAPI.actual.txt over it.\n{diff}");
    }

    /// <summary>Lines only in <paramref name="expected"/> (-) and only in <paramref name="actual"/> (+), in listing order.</summary>
    internal static string Diff(IReadOnlyList<string> expected, IReadOnlyList<string> actual)
    {
        var inExpected = new HashSet<string>(expected, StringComparer.Ordinal);
        var inActual = new HashSet<string>(actual, StringComparer.Ordinal);
        var lines = expected.Where(l => !inActual.Contains(l)).Select(l => "- " + l)
            .Concat(actual.Where(l => !inExpected.Contains(l)).Select(l => "+ " + l))
            .OrderBy(l => l[2..], StringComparer.Ordinal).ThenBy(l => l, StringComparer.Ordinal);
        return string.Join("\n", lines);
    }
}
