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

        // ?run= only fills the box; the person presses Send. The page sets body[data-state] to "done" when every action ran.
        await browser.NavigateAsync(new Uri(bridge.PageUri!, "/?run=hello&name=Chromium"));
        Assert.Equal("open", await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "open", "running", "closed"));
        await browser.EvaluateAsync("document.getElementById('send').click()");
        string state = await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "done", "error", "closed");
        Assert.Equal("done", state);
        // Let the view draw its last frame (it draws on every event; this waits one animation frame for the screenshot).
        await browser.EvaluateAsync("new Promise(r => requestAnimationFrame(() => r(0)))");

        JsonElement drawn = await browser.EvaluateAsync("JSON.parse(JSON.stringify({ executed: bridgePage.executed, issued: bridgePage.issued, arm: bridgePage.arm, " +
            "names: [...document.querySelectorAll('#events li .name')].map(n => n.textContent), status: document.getElementById('statusText').textContent, " +
            "data: document.getElementById('path-data').textContent }))");
        byte[] png = await browser.ScreenshotAsync();
        await File.WriteAllBytesAsync(Path.Combine(AppContext.BaseDirectory, "bridge-page.png"), png);

        // The executed path holds the program's points in order: the start, MoveTo(400,300,500), Move(0,0,250), and AxesTo back
        // home (the robot knows the controller's arm, so the joint move has a pose).
        Assert.Equal("[[[451,0,807.1],[400,300,500],[400,300,750],[451,0,807.1]]]", drawn.GetProperty("executed").GetRawText());
        Assert.Equal("[[[451,0,807.1],[400,300,500],[400,300,750],[451,0,807.1]]]", drawn.GetProperty("issued").GetRawText());
        Assert.Equal(drawn.GetProperty("executed").GetRawText(), JsonDocument.Parse(drawn.GetProperty("data").GetString()!).RootElement.GetProperty("executed").GetRawText());
        string[] names = [.. drawn.GetProperty("names").EnumerateArray().Select(n => n.GetString()!)];
        Assert.Equal(7, names.Count(n => n == "action-issued"));
        Assert.Equal(7, names.Count(n => n == "action-executed"));
        Assert.DoesNotContain("error", names);
        Assert.Equal("Done", drawn.GetProperty("status").GetString());
        Assert.True(png.Length > 10_000 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G', "the screenshot is a PNG with content");
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bridge.Robot.GetExecutedState().Axes);
        // The arm is drawn where the robot is, as machina preview draws it: its joints from the model for the last joint values
        // (the bridge's "arm" message), base to flange, the flange at the tool's home position.
        RobotModel arm = bridge.Robot.Model!;
        string links = "[" + string.Join(",", arm.LinkPositions(new Joints(0, 0, 0, 0, 90, 0)).Select(p =>
            FormattableString.Invariant($"[{Math.Round(p.X, 1) + 0.0},{Math.Round(p.Y, 1) + 0.0},{Math.Round(p.Z, 1) + 0.0}]"))) + "]";
        Assert.Equal(links, drawn.GetProperty("arm").GetRawText());
        Assert.StartsWith("[[0,0,0],", links, StringComparison.Ordinal);
        Assert.EndsWith(",[451,0,807.1]]", links, StringComparison.Ordinal);
    }

    [ChromiumFact]
    public async Task Page_RunParameter_OnlyFillsTheBox_NothingMoves()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { Token = "page-token-1" });
        await using Chromium browser = await Chromium.StartAsync(800, 600);
        await browser.NavigateAsync(new Uri(bridge.PageUri!, "/?run=MoveTo(333,111,444)&authkey=page-token-1"));
        // Before issue 28 the page sent the program in its open handler, so its state was already "running" when connected.
        Assert.Equal("open", await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "open", "running", "closed"));
        Assert.Equal("MoveTo(333,111,444)", (await browser.EvaluateAsync("document.getElementById('program').value")).GetString());
        Assert.Equal(0, (await browser.EvaluateAsync("document.querySelectorAll('#events li').length")).GetInt32());
        Assert.Empty(bridge.Robot.GetPendingActions());
    }

    [ChromiumFact]
    public async Task Page_WithoutTheToken_CannotConnect()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { Token = "page-token-1" });
        await using Chromium browser = await Chromium.StartAsync(800, 600);
        await browser.NavigateAsync(new Uri(bridge.PageUri!, "/?run=hello"));
        Assert.Equal("closed", await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "open", "closed"));
    }

    [ChromiumFact]
    public async Task Page_ActionFailed_ShownInRed()
    {
        await using BridgeServer bridge = await StartAsync();
        await using Chromium browser = await Chromium.StartAsync(800, 600);
        await browser.NavigateAsync(new Uri(bridge.PageUri!, "/"));
        Assert.Equal("open", await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "open", "closed"));
        await EventuallyAsync(() => bridge.ClientCount == 1, "the page is registered");
        var failure = new ActionFailedException(new ActionTranslation(new Vector(5000, 0, 0), false), "Position outside reach", "50050");
        ((IOnlineHost)bridge.Robot).Raise(new ActionFailedArgs(failure, bridge.Robot.GetExecutedState()));
        Assert.Equal("1", await browser.WaitForAsync("String(document.querySelectorAll('#events li.ev-action-failed').length)", "1"));
        JsonElement shown = await browser.EvaluateAsync("(() => { const li = document.querySelector('#events li.ev-action-failed'); " +
            "return { text: li.textContent, color: getComputedStyle(li).color }; })()");
        Assert.Contains("Position outside reach (50050)", shown.GetProperty("text").GetString(), StringComparison.Ordinal);
        Assert.Equal("rgb(207, 34, 46)", shown.GetProperty("color").GetString()); // --bad, #cf222e
    }
}
