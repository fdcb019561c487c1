using System.Globalization;
using System.Xml.Linq;
using Machina.Cli.Preview;

namespace Machina.Tests.Cli;

/// <summary>The reach envelope <c>machina preview --model</c> draws: where the flange can get, checked against the arm's own kinematics.</summary>
public class ReachEnvelopeTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public void Irb120_ReachesAsFarAsItsDataSheetSays()
    {
        ReachEnvelope reach = ReachEnvelope.Of(RobotModels.Get("IRB 120"));

        // ABB's data sheet: 580 mm to the wrist centre; the flange is 72 mm beyond it when the wrist bends outwards.
        Assert.InRange(reach.Radius, 645, 652.5);
        Assert.Equal(reach.Outline[0], reach.Outline[^1]);
        Assert.True(reach.Outline.Count > ReachEnvelope.Directions / 2, $"{reach.Outline.Count} outline points");
    }

    [Theory]
    [InlineData("IRB 120")]
    [InlineData("UR5e")]
    [InlineData("KR 6 R900 sixx")]
    public void EveryFlangePositionTheJointsReach_IsInsideTheOutline(string name)
    {
        RobotModel model = RobotModels.Get(name);
        ReachEnvelope reach = ReachEnvelope.Of(model);
        var random = new Random(20261126);
        for (int n = 0; n < 2000; n++)
        {
            double[] j = new double[6];
            for (int i = 0; i < 6; i++)
            {
                j[i] = model.MinJoints[i] + (random.NextDouble() * (model.MaxJoints[i] - model.MinJoints[i]));
            }
            Vector p = model.Kinematics.Forward(Joints.FromArray(j)).Position;
            double r = Math.Sqrt((p.X * p.X) + (p.Y * p.Y));
            // Sampled, so the line may pass inside the true edge by up to 2 % of the reach.
            double tolerance = 0.02 * reach.Radius;
            Assert.True(Inside(reach.Outline, r, p.Z) || Distance(reach.Outline, r, p.Z) < tolerance, $"{string.Join(", ", j.Select(v => v.ToString("0.#", CultureInfo.InvariantCulture)))} puts the flange at r {r:0.#}, z {p.Z:0.#} mm, outside the outline by {Distance(reach.Outline, r, p.Z):0.#} mm");
            Assert.True(r <= reach.Radius + tolerance, $"r {r:0.#} mm beyond the radius {reach.Radius:0.#} mm");
        }
    }

    [Theory]
    [InlineData("IRB 120")]
    [InlineData("KR 6 R900 sixx")]
    public void APoint30MillimetresOutsideTheOutline_HasNoSolutionInAnyOrientation(string name)
    {
        RobotModel model = RobotModels.Get(name);
        ReachEnvelope reach = ReachEnvelope.Of(model);
        double centreZ = model.LinkPositions(new Joints(0, 0, 0, 0, 0, 0))[1].Z;
        Rotation[] orientations =
        [
            Rotation.Identity, Rotation.FromAxisAngle(0, 1, 0, 90), Rotation.FromAxisAngle(0, 1, 0, 180), Rotation.FromAxisAngle(0, 1, 0, -90),
            Rotation.FromAxisAngle(1, 0, 0, 90), Rotation.FromAxisAngle(1, 0, 0, -90), Rotation.FromAxisAngle(0, 1, 0, 45), Rotation.FromAxisAngle(0, 1, 0, 135),
        ];
        foreach ((double r, double z) in reach.Outline.Where((_, i) => i % 9 == 0))
        {
            double dr = r, dz = z - centreZ, length = Math.Sqrt((dr * dr) + (dz * dz));
            var outside = new Vector(r + (30 * dr / length), 0, z + (30 * dz / length));
            foreach (Rotation rotation in orientations)
            {
                Assert.DoesNotContain(model.Kinematics.Inverse(new Pose(outside, rotation)), model.IsWithinLimits);
            }
        }
    }

    [Fact]
    public async Task Preview_DrawsTheReach_AsACircleFromAbove_AndTheOutlineFromTheFrontAndTheSide()
    {
        using var cli = new CliRunner();
        ReachEnvelope reach = ReachEnvelope.Of(RobotModels.Get("IRB 120"));

        CliResult result = await cli.RunProgramAsync("preview", "MoveTo(300, 0, 400);\nMove(0, 100, 0);\n", "--model", "IRB 120", "--out", "r.svg");

        Assert.Equal(0, result.Exit);
        XDocument svg = XDocument.Load(cli.PathOf("r.svg"));
        double[][] Points(string view) => [.. svg.Descendants(Svg + "polyline").Single(p => (string?)p.Attribute("data-reach") == view)
            .Attribute("points")!.Value.Split(' ').Select(pair => pair.Split(',').Select(v => double.Parse(v, CultureInfo.InvariantCulture)).ToArray())];
        // The file keeps 3 decimals.
        Assert.All(Points("top"), p => Assert.True(Math.Abs(Math.Sqrt((p[0] * p[0]) + (p[1] * p[1])) - reach.Radius) < 0.01, $"{p[0]}, {p[1]}"));
        foreach (string view in new[] { "front", "side" })
        {
            double[][] drawn = Points(view);
            Assert.Equal(reach.Outline.Count, drawn.Length);
            Assert.All(reach.Outline.Zip(drawn), pair => Assert.True(Math.Abs(pair.First.R - pair.Second[0]) < 0.001 && Math.Abs(pair.First.Z - pair.Second[1]) < 0.001,
                $"{view}: {pair.First} drawn at {pair.Second[0]}, {pair.Second[1]}"));
        }
        Assert.Contains(svg.Descendants(Svg + "text"), t => t.Value == $"reach: the flange cannot get beyond this line (up to {reach.Radius:0} mm out)");
    }

    [Fact]
    public async Task AWarningAtTheEnd_HasItsLabelLeftOfTheMarker_AndTheEndsLabelRightOfIt()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("preview", "MoveTo(300, 0, 400);\nMoveTo(900, 0, 400);\n", "--model", "IRB 120", "--out", "w.svg");

        Assert.Equal(0, result.Exit);
        XElement front = XDocument.Load(cli.PathOf("w.svg")).Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "view-front");
        XElement ring = front.Descendants(Svg + "g").Single(g => (string?)g.Attribute("class") == "warning");
        XElement end = front.Descendants(Svg + "g").Single(g => (string?)g.Attribute("class") == "end");
        double ringX = double.Parse(ring.Element(Svg + "circle")!.Attribute("cx")!.Value, CultureInfo.InvariantCulture);
        double endX = double.Parse(end.Element(Svg + "rect")!.Attribute("x")!.Value, CultureInfo.InvariantCulture) + 5.5;
        Assert.Equal(ringX, endX, 3); // one point
        XElement warningText = ring.Element(Svg + "text")!, endText = end.Element(Svg + "text")!;
        Assert.Equal(("!2", "end"), (warningText.Value, (string?)warningText.Attribute("text-anchor")));
        Assert.Equal(ringX - 8, double.Parse(warningText.Attribute("x")!.Value, CultureInfo.InvariantCulture), 3);
        Assert.Equal("end", endText.Value);
        Assert.Equal(endX + 9, double.Parse(endText.Attribute("x")!.Value, CultureInfo.InvariantCulture), 3);
    }

    private static bool Inside(IReadOnlyList<(double R, double Z)> polygon, double r, double z)
    {
        bool inside = false;
        for (int i = 0, j = polygon.Count - 1; i < polygon.Count; j = i++)
        {
            (double ri, double zi) = polygon[i];
            (double rj, double zj) = polygon[j];
            if ((zi > z) != (zj > z) && r < ((rj - ri) * (z - zi) / (zj - zi)) + ri)
            {
                inside = !inside;
            }
        }
        return inside;
    }

    private static double Distance(IReadOnlyList<(double R, double Z)> polyline, double r, double z)
    {
        double best = double.MaxValue;
        for (int i = 1; i < polyline.Count; i++)
        {
            (double ar, double az) = polyline[i - 1];
            (double br, double bz) = polyline[i];
            double dr = br - ar, dz = bz - az, l2 = (dr * dr) + (dz * dz);
            double t = l2 == 0 ? 0 : Math.Clamp((((r - ar) * dr) + ((z - az) * dz)) / l2, 0, 1);
            double er = ar + (t * dr) - r, ez = az + (t * dz) - z;
            best = Math.Min(best, Math.Sqrt((er * er) + (ez * ez)));
        }
        return best;
    }
}
