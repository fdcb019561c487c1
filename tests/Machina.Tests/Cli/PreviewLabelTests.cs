#if NET10_0_OR_GREATER
using System.Text.Json;
using Machina.Tests.Bridge;

namespace Machina.Tests.Cli;

/// <summary>
/// The SVG preview's labels (start, end, base and each warning's line) never overlap, even where markers crowd: measured
/// in headless Chromium from the boxes the browser drew the texts in (getBBox; the 3D page records the boxes of its canvas
/// labels), in each of the three views; and no legend
/// text runs out of its panel.
/// </summary>
public sealed class PreviewLabelTests
{
    /// <summary>Three unreachable targets within 5 mm of each other, and an end 5 mm above the start.</summary>
    private const string Crowded = """
        MoveTo(300, 0, 400);
        MoveTo(900, 0, 400);
        MoveTo(905, 0, 400);
        MoveTo(900, 5, 405);
        MoveTo(300, 0, 405);
        """;

    private const string Overlaps = """
        (() => {
          const found = [];
          let count = 0;
          for (const view of ['top', 'front', 'side']) {
            const texts = [...document.getElementById('view-' + view).querySelectorAll('g.warning > text, g.start > text, g.end > text, g.base > text')];
            count += texts.length;
            const boxes = texts.map(t => { const b = t.getBBox(); return [t.textContent, b.x, b.y, b.x + b.width, b.y + b.height]; });
            for (let i = 0; i < boxes.length; i++) {
              for (let j = i + 1; j < boxes.length; j++) {
                const a = boxes[i], c = boxes[j];
                if (a[1] < c[3] && c[1] < a[3] && a[2] < c[4] && c[2] < a[4]) { found.push(view + ': "' + a[0] + '" and "' + c[0] + '"'); }
              }
            }
          }
          // And no text of the legend runs out of its panel on the right.
          const legend = document.getElementById('legend'), panel = legend.querySelector('rect').getBBox();
          for (const t of legend.querySelectorAll('text')) {
            const b = t.getBBox();
            if (b.x + b.width > panel.x + panel.width - 4) { found.push('legend: "' + t.textContent + '" runs out of the panel'); }
          }
          return JSON.stringify({ count: count, found: found });
        })()
        """;

    [ChromiumFact]
    public async Task Page3d_CrowdedMarkers_TheirLabelsDoNotOverlap_InEveryView()
    {
        using var cli = new CliRunner();
        CliResult result = await cli.RunProgramAsync("preview", Crowded, "--model", "IRB 120", "--out", "crowded.html");
        Assert.Equal(0, result.Exit);

        await using Chromium browser = await Chromium.StartAsync(1280, 800);
        await browser.NavigateAsync(new Uri(cli.PathOf("crowded.html")));
        await browser.WaitForAsync("document.readyState", "complete");
        foreach (string button in new[] { "v-3d", "v-top", "v-front", "v-side" })
        {
            await browser.EvaluateAsync($"document.getElementById('view').removeAttribute('data-labels'), document.getElementById('{button}').click(), 0");
            await browser.WaitForAsync("document.getElementById('view').hasAttribute('data-labels')", "true");
            // The page records each label it drew as [text, left, top, right, bottom] in pixels.
            string json = (await browser.EvaluateAsync("document.getElementById('view').getAttribute('data-labels')")).GetString()!;
            using JsonDocument labels = JsonDocument.Parse(json);
            (string Text, double[] Box)[] boxes = [.. labels.RootElement.EnumerateArray().Select(l =>
                (l[0].GetString()!, new[] { l[1].GetDouble(), l[2].GetDouble(), l[3].GetDouble(), l[4].GetDouble() }))];
            Assert.Equal(["start", "end", "!2", "!3", "!4", "base"], boxes.Select(b => b.Text));
            // Nor over the axes drawn in the bottom left corner (100 x 96 px).
            double height = (await browser.EvaluateAsync("document.getElementById('view').clientHeight")).GetDouble();
            Assert.All(boxes, b => Assert.False(b.Box[0] < 100 && b.Box[3] > height - 96, $"{button}: \"{b.Text}\" is over the axes ({json})."));
            for (int i = 0; i < boxes.Length; i++)
            {
                for (int j = i + 1; j < boxes.Length; j++)
                {
                    double[] a = boxes[i].Box, c = boxes[j].Box;
                    bool overlap = a[0] < c[2] && c[0] < a[2] && a[1] < c[3] && c[1] < a[3];
                    Assert.False(overlap, $"{button}: \"{boxes[i].Text}\" and \"{boxes[j].Text}\" overlap ({json}).");
                }
            }
        }
    }

    [ChromiumFact]
    public async Task Svg_LabelsAreDrawnInTheirMarkersColours()
    {
        using var cli = new CliRunner();
        CliResult result = await cli.RunProgramAsync("preview", Crowded, "--model", "IRB 120", "--out", "c.svg");
        Assert.Equal(0, result.Exit);

        await using Chromium browser = await Chromium.StartAsync(1200, 900);
        await browser.NavigateAsync(new Uri(cli.PathOf("c.svg")));
        await browser.WaitForAsync("document.readyState", "complete");
        async Task<string> FillAsync(string selector) => (await browser.EvaluateAsync($"getComputedStyle(document.querySelector('{selector}')).fill")).GetString()!;

        // The warning's "!2" red (#e53935), the start's label green (#2e7d32), an unlabelled text the default grey-black.
        Assert.Equal("rgb(229, 57, 53)", await FillAsync("#view-top g.warning > text"));
        Assert.Equal("rgb(46, 125, 50)", await FillAsync("#view-top g.start > text"));
        Assert.Equal("rgb(43, 47, 54)", await FillAsync("#view-top > text"));
    }

    [ChromiumFact]
    public async Task Svg_CrowdedMarkers_TheirLabelsDoNotOverlap()
    {
        using var cli = new CliRunner();
        CliResult result = await cli.RunProgramAsync("preview", Crowded, "--model", "IRB 120", "--out", "crowded.svg");
        Assert.Equal(0, result.Exit);
        Assert.Equal(3, result.Stderr.Split('\n').Count(l => l.Contains(": warning: ", StringComparison.Ordinal)));

        await using Chromium browser = await Chromium.StartAsync(1200, 900);
        await browser.NavigateAsync(new Uri(cli.PathOf("crowded.svg")));
        await browser.WaitForAsync("document.readyState", "complete");
        using JsonDocument answer = JsonDocument.Parse((await browser.EvaluateAsync(Overlaps)).GetString()!);

        // In each view: the start, the end, the base and three warnings.
        Assert.Equal(3 * 6, answer.RootElement.GetProperty("count").GetInt32());
        Assert.Empty(answer.RootElement.GetProperty("found").EnumerateArray().Select(f => f.GetString()));
    }
}
#endif
