using System.Globalization;
using System.Text.Json;
using System.Text.RegularExpressions;
using System.Xml.Linq;

namespace Machina.Tests.Cli;

public class PreviewCommandTests
{
    private const string Program = """
        MoveTo(300, -100, 400);
        Move(0, 0, -100);
        Move(150, 0, 0);
        MotionMode("joint");
        MoveTo(450, 100, 300);
        MotionMode("linear");
        ArcMotionTo(375, 0, 360, 300, 100, 300);
        Rotate(0, 0, 1, 10);
        MoveTo(300, 100, 450);
        """;

    /// <summary>The program's targets, worked out by hand: the first absolute position, then each motion that moves the tip.</summary>
    private static readonly double[][] Targets =
    [
        [300, -100, 400], [300, -100, 300], [450, -100, 300], [450, 100, 300], [300, 100, 300], [300, 100, 450],
    ];

    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public async Task Preview_Svg_DrawsTheProgramsTargetsInEveryView()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("preview", Program, "--out", "pics/p.svg");

        Assert.Equal(0, result.Exit);
        // At Machina's 20 mm/s: 100 + 150 mm, the joint move's 200 mm (no model: timed by its straight line), the arc's 329.47 mm,
        // the 10° turn at 20°/s and 150 mm: 46.97 s; the first move starts from wherever the robot stands.
        Assert.Equal(["pics/p.svg", "Estimated cycle time on a generic controller (no --model): 47.0 s (motion 47.0 s, waits 0.00 s; " +
            "blends not shortened); 1 motion not timed: where it starts is not known (before the first absolute position, or joints without a --model)."],
            result.Lines);
        XDocument svg = XDocument.Load(cli.PathOf("pics/p.svg"));
        foreach ((string view, int h, int v) in new[] { ("top", 0, 1), ("front", 0, 2), ("side", 1, 2) })
        {
            XElement group = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("data-view") == view);
            double[][] circles = group.Descendants(Svg + "circle").Select(c => new[] { D(c, "cx"), D(c, "cy") }).ToArray();
            Assert.Equal(Targets.Select(t => new[] { t[h], t[v] }), circles);
            // The polylines pass through every target, in order, with the arc sampled between its ends.
            List<double[]> drawn = group.Descendants(Svg + "polyline").SelectMany(p => Points(p)).ToList();
            int at = 0;
            foreach (double[] target in Targets)
            {
                at = drawn.FindIndex(at, p => Math.Abs(p[0] - target[h]) < 1e-3 && Math.Abs(p[1] - target[v]) < 1e-3);
                Assert.True(at >= 0, $"{view}: target [{string.Join(", ", target)}] is not drawn in order");
            }
        }
        XElement top = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("data-view") == "top");
        Assert.Equal(["linear", "joint", "arc", "linear"], top.Descendants(Svg + "polyline").Select(p => (string)p.Attribute("data-kind")!));
        Assert.Equal(3, svg.Descendants(Svg + "g").Count(g => (string?)g.Attribute("class") == "start"));
        Assert.Equal(3, svg.Descendants(Svg + "g").Count(g => (string?)g.Attribute("class") == "end"));
    }

    [Fact]
    public async Task Preview_Html_EmbedsTheProgramsTargetsAndIsSelfContained()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("preview", Program, "--out", "p.html");

        Assert.Equal(0, result.Exit);
        string html = File.ReadAllText(cli.PathOf("p.html"));
        using JsonDocument data = PathData(html);
        Assert.Equal(Targets, Vectors(data.RootElement.GetProperty("targets")));
        Assert.Equal(Targets[0], data.RootElement.GetProperty("start").EnumerateArray().Select(v => v.GetDouble()));
        Assert.Equal(Targets[^1], data.RootElement.GetProperty("end").EnumerateArray().Select(v => v.GetDouble()));
        Assert.Equal(["linear", "linear", "joint", "arc", "linear"], data.RootElement.GetProperty("segments").EnumerateArray().Select(s => s.GetProperty("kind").GetString()));
        Assert.Equal([2, 3, 5, 7, 9], data.RootElement.GetProperty("segments").EnumerateArray().Select(s => s.GetProperty("line").GetInt32()));
        // The arc is drawn along its circle: every sample is as far from the circle's centre as its three points.
        double[][] arc = Vectors(data.RootElement.GetProperty("segments")[3].GetProperty("points"));
        double[] centre = Circumcentre([450, 100, 300], [375, 0, 360], [300, 100, 300]);
        double radius = Distance(centre, [450, 100, 300]);
        Assert.True(arc.Length > 10);
        Assert.All(arc, p => Assert.Equal(radius, Distance(centre, p), 2));
        Assert.Equal([375, 0, 360], arc.MinBy(p => Distance(p, [375, 0, 360]))!);
        Assert.DoesNotMatch("(src|href)=\"(https?:)?//", html);
        Assert.Contains("getContext('2d')", html, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Preview_WithModel_DrawsTheWarningWhereItHappens()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("preview", "MoveTo(300, 0, 400);\nMoveTo(900, 0, 400);\nMoveTo(300, 0, 300);\n", "--model", "IRB 120", "--out", "p.svg");

        Assert.Equal(0, result.Exit);
        Assert.Contains("p.machina:2:1: warning: MoveTo(900,0,400); Unreachable", result.Stderr, StringComparison.Ordinal);
        XDocument svg = XDocument.Load(cli.PathOf("p.svg"));
        XElement[] warnings = svg.Descendants(Svg + "g").Where(g => (string?)g.Attribute("class") == "warning").ToArray();
        Assert.Equal(3, warnings.Length); // once in each view
        Assert.All(warnings, w => Assert.StartsWith("line 2: MoveTo(900,0,400); Unreachable", w.Element(Svg + "title")!.Value, StringComparison.Ordinal));
        // In the top view the marker sits on the drawn target (900, 0): apply the view's transform to it.
        XElement top = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("data-view") == "top");
        (double sx, double sy) = Transform(top, 900, 0);
        XElement ring = warnings.Select(w => w.Element(Svg + "circle")!).First(c => Math.Abs(D(c, "cx") - sx) < 0.01);
        Assert.Equal(sy, D(ring, "cy"), 2);
    }

    [Fact]
    public async Task Preview_SvgWithModel_DrawsTheArmAtStartAndEnd_FromItsJoints_AndTheBase()
    {
        using var cli = new CliRunner();
        Robot robot = Robot.Create("T", "ABB", "IRB 120");
        robot.MoveTo(300, 0, 400);
        Joints start = robot.GetIssuedState().Axes!.Value;
        robot.MoveTo(250, 250, 300);
        Joints end = robot.GetIssuedState().Axes!.Value;

        CliResult result = await cli.RunProgramAsync("preview", "MoveTo(300, 0, 400);\nMoveTo(250, 250, 300);\n", "--model", "IRB 120", "--out", "p.svg");

        Assert.Equal(0, result.Exit);
        XDocument svg = XDocument.Load(cli.PathOf("p.svg"));
        XElement front = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("data-view") == "front");
        XElement[] arms = front.Descendants(Svg + "polyline").Where(l => ((string?)l.Attribute("class"))?.StartsWith("arm ", StringComparison.Ordinal) == true).ToArray();
        Assert.Equal(["start", "end"], arms.Select(a => (string?)a.Attribute("data-arm")));
        // The front view draws X and Z of the arm's joints, base to flange: the model's link positions for the issued joints.
        foreach ((XElement arm, Joints joints) in arms.Zip([start, end]))
        {
            double[][] drawn = [.. Points(arm)];
            IReadOnlyList<Vector> expected = RobotModels.Get("IRB 120").LinkPositions(joints);
            Assert.Equal(expected.Count, drawn.Length);
            for (int i = 0; i < drawn.Length; i++)
            {
                Assert.Equal(expected[i].X, drawn[i][0], 3);
                Assert.Equal(expected[i].Z, drawn[i][1], 3);
            }
        }
        Assert.Equal([0, 0], Points(arms[0]).First());   // from the base
        Assert.Equal(3, svg.Descendants(Svg + "g").Count(g => (string?)g.Attribute("class") == "base"));
        Assert.Contains("the arm at the start (light) and the end (dark), base at 0,0,0", svg.ToString(), StringComparison.Ordinal);

        // The 3D page carries the same arms in its JSON (rounded to 0.001 mm).
        CliResult page = await cli.RunProgramAsync("preview", "MoveTo(300, 0, 400);\nMoveTo(250, 250, 300);\n", "--model", "IRB 120", "--out", "p.html");
        Assert.Equal(0, page.Exit);
        using JsonDocument data = PathData(File.ReadAllText(cli.PathOf("p.html")));
        JsonElement[] jsonArms = [.. data.RootElement.GetProperty("arms").EnumerateArray()];
        Assert.Equal(["start", "end"], jsonArms.Select(a => a.GetProperty("label").GetString()));
        double[][] endPoints = Vectors(jsonArms[1].GetProperty("points"));
        Vector flange = RobotModels.Get("IRB 120").Kinematics.Forward(end).Position;
        Assert.Equal([Math.Round(flange.X, 3), Math.Round(flange.Y, 3), Math.Round(flange.Z, 3)], endPoints[^1]);
    }

    [Fact]
    public void Wrap_BreaksBetweenWords_AndCutsOnlyPastTheLastLine()
    {
        Assert.Equal(["line 17: MoveTo(620,0,450); Unreachable:", "the target is out of reach."],
            Machina.Cli.Preview.SvgWriter.Wrap("line 17: MoveTo(620,0,450); Unreachable: the target is out of reach.", 42, 3));
        Assert.Equal(["aaaa bbbb", "cccc dddd", "eeee ffff…"], Machina.Cli.Preview.SvgWriter.Wrap("aaaa bbbb cccc dddd eeee ffff gggg", 10, 3));
    }

    [Fact]
    public async Task Preview_JointMoveWithModel_FollowsTheArmsJoints()
    {
        using var cli = new CliRunner();
        cli.Write("p.machina", "MoveTo(300, 0, 400);\nMotionMode(\"joint\");\nMoveTo(250, 250, 300);\n");
        Robot robot = Robot.Create("T", "ABB", "IRB 120");
        robot.MoveTo(300, 0, 400);
        Joints a = robot.GetIssuedState().Axes!.Value;
        robot.MotionMode("joint");
        robot.MoveTo(250, 250, 300);
        Joints b = robot.GetIssuedState().Axes!.Value;

        CliResult result = await cli.RunAsync("preview", "p.machina", "--model", "IRB 120", "--out", "p.html");

        Assert.Equal(0, result.Exit);
        string html = File.ReadAllText(cli.PathOf("p.html"));
        using JsonDocument data = PathData(html);
        JsonElement joint = data.RootElement.GetProperty("segments").EnumerateArray().Single();
        Assert.Equal("joint", joint.GetProperty("kind").GetString());
        double[][] points = Vectors(joint.GetProperty("points"));
        Assert.Equal(25, points.Length);
        Assert.Equal([300, 0, 400], points[0]);
        Assert.Equal([250, 250, 300], points[^1]);
        // Half way, every joint is half way: the tip is the forward kinematics of the mean joints (no tool).
        Vector middle = RobotModels.Get("IRB 120").Kinematics.Forward(new Joints(
            (a.J1 + b.J1) / 2, (a.J2 + b.J2) / 2, (a.J3 + b.J3) / 2, (a.J4 + b.J4) / 2, (a.J5 + b.J5) / 2, (a.J6 + b.J6) / 2)).Position;
        Assert.Equal(middle.X, points[12][0], 3);
        Assert.Equal(middle.Y, points[12][1], 3);
        Assert.Equal(middle.Z, points[12][2], 3);
        // A joint move is not a straight line: the middle is off the chord.
        Assert.True(Math.Abs(middle.Z - 350) > 1 || Math.Abs(middle.X - 275) > 1 || Math.Abs(middle.Y - 125) > 1);
        Assert.Contains("joint move (the tool path as the joints turn)", html, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Preview_Printer_DrawsTravelAndExtrusion()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("preview", "MoveTo(0, 0, 0.2);\nMoveTo(20, 0, 0.2);\nExtrude(true);\nMove(0, 20, 0);\nMove(-20, 0, 0);\nExtrude(false);\nMove(0, 0, 5);\n", "--brand", "marlin", "--out", "p.html");

        Assert.Equal(0, result.Exit);
        string html = File.ReadAllText(cli.PathOf("p.html"));
        using JsonDocument data = PathData(html);
        Assert.Equal(["travel", "extrusion", "extrusion", "travel"], data.RootElement.GetProperty("segments").EnumerateArray().Select(s => s.GetProperty("kind").GetString()));
    }

    [Fact]
    public async Task Preview_UnknownPictureKind_IsAUsageError()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("preview", Program, "--out", "p.png");

        Assert.Equal(2, result.Exit);
        Assert.Contains("--out must end in .svg", result.Stderr, StringComparison.Ordinal);
    }

    /// <summary>The path data a page embeds (its "machina-path" JSON script).</summary>
    private static JsonDocument PathData(string html)
    {
        Match json = Regex.Match(html, "<script type=\"application/json\" id=\"machina-path\">(.*?)</script>", RegexOptions.Singleline);
        Assert.True(json.Success, "the page embeds no path data");
        return JsonDocument.Parse(json.Groups[1].Value);
    }

    /// <summary>A JSON array of points as arrays of numbers.</summary>
    private static double[][] Vectors(JsonElement array) =>
        [.. array.EnumerateArray().Select(p => p.EnumerateArray().Select(v => v.GetDouble()).ToArray())];

    /// <summary>The centre of the circle through three points: the point of their plane equally far from all three (Cramer's rule).</summary>
    private static double[] Circumcentre(double[] a, double[] b, double[] c)
    {
        double[] ab = Sub(b, a), ac = Sub(c, a), n = Cross(ab, ac);
        // Solve (p − a)·ab = |ab|²/2, (p − a)·ac = |ac|²/2, (p − a)·n = 0.
        double[][] m = [ab, ac, n];
        double[] r = [Dot(ab, ab) / 2, Dot(ac, ac) / 2, 0];
        double det = Dot(m[0], Cross(m[1], m[2]));
        double[] x = new double[3];
        for (int i = 0; i < 3; i++)
        {
            double[][] mi = m.Select((row, k) => row.Select((v, j) => j == i ? r[k] : v).ToArray()).ToArray();
            x[i] = Dot(mi[0], Cross(mi[1], mi[2])) / det;
        }
        return [a[0] + x[0], a[1] + x[1], a[2] + x[2]];
    }

    private static double[] Sub(double[] p, double[] q) => [p[0] - q[0], p[1] - q[1], p[2] - q[2]];

    private static double Dot(double[] p, double[] q) => (p[0] * q[0]) + (p[1] * q[1]) + (p[2] * q[2]);

    private static double[] Cross(double[] p, double[] q) => [(p[1] * q[2]) - (p[2] * q[1]), (p[2] * q[0]) - (p[0] * q[2]), (p[0] * q[1]) - (p[1] * q[0])];

    private static double Distance(double[] p, double[] q) => Math.Sqrt(Dot(Sub(p, q), Sub(p, q)));

    private static double D(XElement e, string attribute) => double.Parse((string)e.Attribute(attribute)!, CultureInfo.InvariantCulture);

    private static IEnumerable<double[]> Points(XElement polyline) => ((string)polyline.Attribute("points")!)
        .Split(' ').Select(p => p.Split(',').Select(v => double.Parse(v, CultureInfo.InvariantCulture)).ToArray());

    /// <summary>Applies "translate(a b) scale(s t) translate(c d)" to a point.</summary>
    private static (double X, double Y) Transform(XElement group, double u, double v)
    {
        double[] n = Regex.Matches((string)group.Attribute("transform")!, @"-?[\d.]+").Select(m => double.Parse(m.Value, CultureInfo.InvariantCulture)).ToArray();
        return (n[0] + (n[2] * (u + n[4])), n[1] + (n[3] * (v + n[5])));
    }
}
