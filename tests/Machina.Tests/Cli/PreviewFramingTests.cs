#if NET10_0_OR_GREATER
using System.Globalization;
using Machina.Tests.Bridge;

namespace Machina.Tests.Cli;

/// <summary>
/// The 3D preview page opens framed on the whole drawing, in every standard view: each point of the path, its targets and
/// the arm lands inside the canvas with room for the labels, and the drawing fills most of it. Measured in headless
/// Chromium from where the page says it drew the points (the canvas's data-drawn: left, top, right, bottom in pixels).
/// </summary>
public sealed class PreviewFramingTests
{
    /// <summary>The corners of a 400 mm cube: the worst case for the slanted 3D view, whose picture is taller than any side.</summary>
    private const string Cube = """
        MoveTo(200, -200, 200);
        MoveTo(600, -200, 200);
        MoveTo(600, 200, 200);
        MoveTo(200, 200, 200);
        MoveTo(200, -200, 600);
        MoveTo(600, -200, 600);
        MoveTo(600, 200, 600);
        MoveTo(200, 200, 600);
        """;

    [ChromiumFact]
    public async Task Preview3d_FramesTheWholePath_InEveryView()
    {
        using var cli = new CliRunner();
        CliResult result = await cli.RunProgramAsync("preview", Cube, "--out", "cube.html");
        Assert.Equal(0, result.Exit);

        foreach (string button in new[] { "v-3d", "v-top", "v-front", "v-side" })
        {
            (double[] drawn, double width, double height) = await DrawnAsync(cli.PathOf("cube.html"), button);
            AssertFramed(drawn, width, height, button);
        }
    }

    [ChromiumFact]
    public async Task Preview3d_WithTheArm_FramesTheArmAndThePath()
    {
        using var cli = new CliRunner();
        CliResult result = await cli.RunProgramAsync("preview", "MoveTo(300, -100, 400);\nMoveTo(400, 100, 300);\n", "--model", "IRB 120", "--out", "arm.html");
        Assert.Equal(0, result.Exit);

        (double[] drawn, double width, double height) = await DrawnAsync(cli.PathOf("arm.html"), "v-3d");

        AssertFramed(drawn, width, height, "v-3d");
    }

    private static void AssertFramed(double[] drawn, double width, double height, string view)
    {
        string where = $"{view}: drawn {string.Join(", ", drawn.Select(d => d.ToString(CultureInfo.InvariantCulture)))} on a {width} x {height} canvas";
        // Inside, with room for a label beside the outermost markers.
        Assert.True(drawn[0] >= 40 && drawn[1] >= 40 && drawn[2] <= width - 40 && drawn[3] <= height - 40, $"Not all inside: {where}");
        // And not lost in the middle: the drawing spans at least 80 % of the canvas across or down.
        Assert.True(drawn[2] - drawn[0] >= 0.8 * (width - 96) || drawn[3] - drawn[1] >= 0.8 * (height - 96), $"Too small: {where}");
    }

    private static async Task<(double[] Drawn, double Width, double Height)> DrawnAsync(string page, string button)
    {
        await using Chromium browser = await Chromium.StartAsync(1280, 800);
        await browser.NavigateAsync(new Uri(page));
        await browser.WaitForAsync("document.readyState", "complete");
        await browser.EvaluateAsync($"document.getElementById('{button}').click(), 0");
        await browser.WaitForAsync("document.getElementById('view').hasAttribute('data-drawn')", "true");
        string drawn = (await browser.EvaluateAsync("document.getElementById('view').getAttribute('data-drawn')")).GetString()!;
        double width = (await browser.EvaluateAsync("document.getElementById('view').clientWidth")).GetDouble();
        double height = (await browser.EvaluateAsync("document.getElementById('view').clientHeight")).GetDouble();
        return ([.. drawn.Split(' ').Select(v => double.Parse(v, CultureInfo.InvariantCulture))], width, height);
    }
}
#endif
