using System.Text;

namespace Machina.Tests.Brands.Abb;

/// <summary>The robtarget writer that keeps the last orientation's text writes exactly what <c>RapidText.RobTarget</c> writes.</summary>
public class RapidTargetTextTests
{
    [Fact]
    public void Append_ChangingOrientationAxesAndConf_SameTextAsRobTarget()
    {
        var cached = new RapidTargetText();
        Rotation flat = Rotation.Identity;
        Rotation turned = new(new Vector(0, 0, 1), 90);
        var axes = new ExternalAxes(100, null, 2.5);
        (Vector P, Rotation R, ExternalAxes? E, double? Arm, AbbConfiguration? C)[] targets =
        [
            (new Vector(400, 300, 500), flat, null, null, null),
            (new Vector(401.5, -0.25, 500), flat, null, null, null),
            (new Vector(401.5, -0.25, 500), turned, null, null, null),
            (new Vector(1, 2, 3), turned, axes, null, null),
            (new Vector(1, 2, 3), turned, axes, 45, null),
            (new Vector(1, 2, 3), turned, axes, 45, new AbbConfiguration(0, -1, 2, 1)),
            (new Vector(7, 8, 9), flat, null, null, null),
        ];
        var lines = new List<string>();
        foreach (var t in targets)
        {
            string expected = new StringBuilder().RobTarget(t.P, t.R, t.E, t.Arm, t.C).ToString();
            string actual = cached.Append(new StringBuilder(), t.P, t.R, t.E, t.Arm, t.C).ToString();
            Assert.Equal(expected, actual);
            lines.Add(actual);
        }
        Assert.Equal("[[401.5, -0.25, 500], [0.7071, 0, 0, 0.7071], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]]", lines[2]);
        Assert.Equal("[[7, 8, 9], [1, 0, 0, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]]", lines[6]);
    }
}
