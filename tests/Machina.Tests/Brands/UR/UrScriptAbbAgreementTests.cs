using System.Globalization;
using System.Text.RegularExpressions;
using Machina.Tests.Support;

namespace Machina.Tests.Brands.UR;

/// <summary>The same program compiled for ABB and UR must reach the same poses once units are converted.</summary>
public partial class UrScriptAbbAgreementTests
{
    [GeneratedRegex(@"Move[LJ] \[\[([-\d.E+]+), ([-\d.E+]+), ([-\d.E+]+)\], \[([-\d.E+]+), ([-\d.E+]+), ([-\d.E+]+), ([-\d.E+]+)\]")]
    private static partial Regex RapidPose();

    [GeneratedRegex(@"move[pj]\(p\[([-\d.E+]+),([-\d.E+]+),([-\d.E+]+),([-\d.E+]+),([-\d.E+]+),([-\d.E+]+)\]")]
    private static partial Regex UrPose();

    public static TheoryData<string> Programs => [.. ReferencePrograms.All.Keys];

    private static double D(Group g) => double.Parse(g.Value, CultureInfo.InvariantCulture);

    [Theory]
    [MemberData(nameof(Programs))]
    public void Compile_AbbAndUr_ReachTheSamePoses(string name)
    {
        var abb = ReferencePrograms.Issue(name, RobotType.ABB).Compile(RobotType.ABB).GetFile("mod")!.Lines
            .Select(l => RapidPose().Match(l)).Where(m => m.Success).ToList();
        var ur = ReferencePrograms.Issue(name, RobotType.UR).Compile(RobotType.UR).GetFile("script")!.Lines
            .Select(l => UrPose().Match(l)).Where(m => m.Success).ToList();

        Assert.NotEmpty(abb);
        Assert.Equal(abb.Count, ur.Count);
        for (int i = 0; i < abb.Count; i++)
        {
            var a = abb[i].Groups;
            var u = ur[i].Groups;
            Assert.Equal(D(a[1]), D(u[1]) * 1000, 3);
            Assert.Equal(D(a[2]), D(u[2]) * 1000, 3);
            Assert.Equal(D(a[3]), D(u[3]) * 1000, 3);
            Rotation fromAbb = Rotation.FromQuaternion(D(a[4]), D(a[5]), D(a[6]), D(a[7]));
            double toDegrees = 180 / Math.PI;
            Rotation fromUr = Rotation.FromRotationVector(new Vector(D(u[4]) * toDegrees, D(u[5]) * toDegrees, D(u[6]) * toDegrees));
            Assert.True(fromAbb.AngleTo(fromUr) < 0.02, $"{name} pose {i}: {fromAbb} vs {fromUr}");
        }
    }
}
