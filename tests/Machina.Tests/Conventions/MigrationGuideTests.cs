namespace Machina.Tests.Conventions;

/// <summary>
/// docs/migrating.md accounts for every public member of the original Machina.NET (listed in OriginalPublicAPI.txt): its table
/// is generated from the comparison with our public API, and only its Replacement column is written by hand. When the table
/// is out of date the test writes docs/migrating.generated.md (git-ignored), the whole document with the table regenerated and
/// the hand-written replacements kept: copy it over docs/migrating.md and fill in every TODO.
/// </summary>
public class MigrationGuideTests
{
    internal const string Begin = "<!-- BEGIN GENERATED TABLE (tests/Machina.Tests/Conventions/MigrationGuideTests.cs): edit only the Replacement column -->";
    internal const string End = "<!-- END GENERATED TABLE -->";

    private static IReadOnlyList<string> Original() =>
        PublicApiListing.Parse(File.ReadAllText(Path.Combine(ConventionTests.RepositoryRoot(), "tests/Machina.Tests/Conventions/OriginalPublicAPI.txt")));

    private static List<Verdict> Verdicts() =>
        OriginalApiComparison.Compare(Original(), PublicApiListing.Describe(typeof(Robot).Assembly, annotations: false),
            OriginalMeaningChanges.All.Keys.ToHashSet(StringComparer.Ordinal));

    private static Verdict VerdictOf(List<Verdict> verdicts, string originalLine) =>
        verdicts.Single(v => v.Original.Line == originalLine);

    [Fact]
    public void MigrationGuide_AccountsForEveryOriginalMember()
    {
        string path = Path.Combine(ConventionTests.RepositoryRoot(), "docs", "migrating.md");
        string doc = File.ReadAllText(path).ReplaceLineEndings("\n");
        int begin = doc.IndexOf(Begin, StringComparison.Ordinal), end = doc.IndexOf(End, StringComparison.Ordinal);
        Assert.True(begin >= 0 && end > begin, $"docs/migrating.md lacks the lines {Begin} and {End}.");

        var replacements = OriginalApiComparison.ReadReplacements(doc);
        foreach ((string line, string reason) in OriginalMeaningChanges.All)
        {
            replacements.TryAdd(line, reason);
        }
        string table = OriginalApiComparison.Table(Verdicts(), replacements);
        string current = doc[(begin + Begin.Length)..end].Trim('\n');
        int todo = table.Split('\n').Count(l => l.EndsWith("| TODO |", StringComparison.Ordinal));
        if (current == table.Trim('\n') && todo == 0)
        {
            return;
        }
        string generated = doc[..(begin + Begin.Length)] + "\n" + table.Trim('\n') + "\n" + doc[end..];
        File.WriteAllText(Path.Combine(ConventionTests.RepositoryRoot(), "docs", "migrating.generated.md"), generated);
        var currentRows = current.Split('\n').ToHashSet(StringComparer.Ordinal);
        var changedRows = table.Trim('\n').Split('\n').Where(l => !currentRows.Contains(l)).Take(30);
        Assert.Fail($"docs/migrating.md is out of date with the comparison ({todo} rows still say TODO). docs/migrating.generated.md " +
            "has the regenerated table: copy it over docs/migrating.md and write each TODO replacement. New or changed rows:\n" +
            string.Join("\n", changedRows));
    }

    [Fact]
    public void MeaningChanges_AreAllMembersOfTheOriginal()
    {
        var original = Original().ToHashSet(StringComparer.Ordinal);

        Assert.All(OriginalMeaningChanges.All.Keys, line => Assert.Contains(line, original));
    }

    [Fact]
    public void OriginalListing_HasTheOriginalsRobotAndGeometry()
    {
        var entries = OriginalApiComparison.Parse(Original());

        Assert.Equal(112, entries.Count(e => e.Owner == "Machina.Robot" && !e.IsType));
        Assert.Equal(4, entries.Count(e => e.IsType && e.Kind == "type:delegate" && e.Owner.StartsWith("Machina.Robot.", StringComparison.Ordinal)));
        Assert.Equal(323, entries.Count(e => e.Owner.StartsWith("Machina.Types.Geometry.", StringComparison.Ordinal) && !e.IsType));
    }

    [Theory]
    [InlineData("Machina.Types.Geometry.Vector.DistanceTo(Machina.Types.Geometry.Vector other) -> double")]
    [InlineData("static Machina.Types.Geometry.Vector.AngleBetween(Machina.Types.Geometry.Vector p1, Machina.Types.Geometry.Vector p2) -> double")]
    [InlineData("Machina.Types.Geometry.Rotation.Rotation(double axisX, double axisY, double axisZ, double angleDegrees)")]
    [InlineData("Machina.Types.Geometry.Orientation.ToQuaternion() -> Machina.Types.Geometry.Quaternion")]
    [InlineData("Machina.Types.Geometry.RotationMatrix.RotationMatrix()")]
    [InlineData("Machina.Types.Geometry.Quaternion.Quaternion()")]
    [InlineData("static Machina.Types.Geometry.Rotation.implicit operator Machina.Types.Geometry.Rotation(Machina.Types.Geometry.Orientation or) -> Machina.Types.Geometry.Rotation")]
    [InlineData("event Machina.Robot.ActionIssued -> Machina.Robot.ActionIssuedHandler")]
    [InlineData("delegate Machina.Robot.MotionUpdateHandler(object sender, Machina.MotionUpdateArgs args) -> void")]
    [InlineData("Machina.Robot.MoveTo(Machina.Types.Geometry.Point position) -> bool")]
    public void Compare_PortedMember_IsKept(string originalLine)
    {
        Assert.Equal("kept", VerdictOf(Verdicts(), originalLine).Status);
    }

    [Theory]
    [InlineData("Machina.Types.Geometry.ExternalAxes.this[int i] { get; set; } -> double?", "removed")]
    [InlineData("Machina.Types.Geometry.Rotation.Angle { get; } -> double", "changed")]
    [InlineData("Machina.Types.Geometry.Vector.Normalize() -> bool", "removed")]
    [InlineData("Machina.Types.Geometry.Joints.J1 (field) -> double", "changed")]
    [InlineData("class Machina.Types.Geometry.Vector : Machina.Types.Geometry.Geometry", "changed")]
    [InlineData("abstract class Machina.Types.Geometry.Geometry", "removed")]
    public void Compare_MemberThatWouldNotPortSilently_IsNotKept(string originalLine, string status)
    {
        Assert.Equal(status, VerdictOf(Verdicts(), originalLine).Status);
    }

    [Fact]
    public void Compare_MutableFieldAgainstReadOnlyProperty_IsChangedNotKept()
    {
        string[] original = ["class Machina.Types.Geometry.Joints", "Machina.Types.Geometry.Joints.J1 (field) -> double", "Machina.Types.Geometry.Joints.Norm() -> double"];
        string[] ours = ["readonly struct Machina.Joints", "Machina.Joints.J1 { get; init; } -> double"];

        var verdicts = OriginalApiComparison.Compare(original, ours, new HashSet<string>());

        Assert.Equal(["changed", "changed", "removed"], verdicts.Select(v => v.Status));
        Assert.Equal("Machina.Joints", verdicts[1].OurOwner);
    }
}
