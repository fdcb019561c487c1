using System.Text.Json;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

public class BridgePageTests
{
    [ChromiumFact]
    public async Task Page_HeadlessChromium_RunsHelloRobotAndDrawsItsPoints()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { SimulationSpeed = 10 });
        await using Chromium browser = await Chromium.StartAsync(1280, 800);

        // ?run= makes the page send the program as soon as it is connected; it sets body[data-state] to "done" when every action ran.
        await browser.NavigateAsync(new Uri(bridge.PageUri!, "/?run=hello&name=Chromium"));
        string state = await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "done", "error", "closed");
        Assert.Equal("done", state);
        // Let the view draw its last frame (it draws on every event; this waits one animation frame for the screenshot).
        await browser.EvaluateAsync("new Promise(r => requestAnimationFrame(() => r(0)))");

        JsonElement drawn = await browser.EvaluateAsync("JSON.parse(JSON.stringify({ executed: bridgePage.executed, issued: bridgePage.issued, " +
            "names: [...document.querySelectorAll('#events li .name')].map(n => n.textContent), status: document.getElementById('statusText').textContent, " +
            "data: document.getElementById('path-data').textContent }))");
        byte[] png = await browser.ScreenshotAsync();
        await File.WriteAllBytesAsync(Path.Combine(AppContext.BaseDirectory, "bridge-page.png"), png);

        // The executed path holds the program's points in order: the start, MoveTo(400,300,500), then Move(0,0,250); AxesTo ends the segment.
        Assert.Equal("[[[451,0,807.1],[400,300,500],[400,300,750]],[]]", drawn.GetProperty("executed").GetRawText());
        Assert.Equal("[[[451,0,807.1],[400,300,500],[400,300,750]],[]]", drawn.GetProperty("issued").GetRawText());
        Assert.Equal(drawn.GetProperty("executed").GetRawText(), JsonDocument.Parse(drawn.GetProperty("data").GetString()!).RootElement.GetProperty("executed").GetRawText());
        string[] names = [.. drawn.GetProperty("names").EnumerateArray().Select(n => n.GetString()!)];
        Assert.Equal(7, names.Count(n => n == "action-issued"));
        Assert.Equal(7, names.Count(n => n == "action-executed"));
        Assert.DoesNotContain("error", names);
        Assert.Equal("Done", drawn.GetProperty("status").GetString());
        Assert.True(png.Length > 10_000 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G', "the screenshot is a PNG with content");
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bridge.Robot.GetExecutedState().Axes);
    }
}
