using System.Globalization;
using System.Text.RegularExpressions;
using System.Xml.Linq;

namespace Machina.Tests.Cli;

/// <summary>
/// The SVG legend's warning list is never cut: each warning is listed whole or counted in a last "… and N more" line, and
/// every line of the legend stays inside its panel.
/// </summary>
public sealed partial class PreviewLegendTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public async Task Svg_WarningsThatDoNotFit_AreCountedOnALastLine_InsideThePanel()
    {
        using var cli = new CliRunner();
        // Three unreachable targets: with the arm's and the reach's lines, the legend has room for two of them.
        CliResult result = await cli.RunProgramAsync("preview",
            "MoveTo(300, 0, 400);\nMoveTo(900, 0, 400);\nMoveTo(905, 0, 400);\nMoveTo(900, 5, 405);\nMoveTo(300, 0, 405);\n",
            "--model", "IRB 120", "--out", "w.svg");
        Assert.Equal(0, result.Exit);

        XElement legend = XDocument.Load(cli.PathOf("w.svg")).Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "legend");
        XElement panel = legend.Element(Svg + "rect")!;
        double bottom = D(panel, "y") + D(panel, "height");
        XElement[] texts = [.. legend.Elements(Svg + "text")];
        Assert.All(texts, t => Assert.True(D(t, "y") <= bottom - 4, $"\"{t.Value}\" at y {D(t, "y")} is below the panel's bottom ({bottom})."));
        string[] listed = [.. texts.Select(t => t.Value).Where(v => v.StartsWith("line ", StringComparison.Ordinal))];
        Assert.Equal(["line 2: MoveTo(900,0,400); Unreachable: the target [900, 0, 400] is out of reach of the ABB",
            "line 3: MoveTo(905,0,400); Unreachable: the target [905, 0, 400] is out of reach of the ABB"], listed);
        string more = Assert.Single(texts, t => t.Value.StartsWith("… and ", StringComparison.Ordinal)).Value;
        Assert.Equal("… and 1 more (every warning is on the command's output, with its line)", more);
        Assert.Equal(3, listed.Length + int.Parse(MoreCount().Match(more).Groups[1].Value, CultureInfo.InvariantCulture));
    }

    [GeneratedRegex(@"… and (\d+) more")]
    private static partial Regex MoreCount();

    private static double D(XElement e, string name) => double.Parse(e.Attribute(name)!.Value, CultureInfo.InvariantCulture);
}
