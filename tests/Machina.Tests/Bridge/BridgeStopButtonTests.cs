using System.Text.Json;
using Machina.Bridge;
using Machina.Tests.Support;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

/// <summary>
/// The page's Pause, Resume and Stop buttons (messages #pause, #resume, #stop) on the bridge's embedded ABB twin, which runs the
/// RAPID driver: a slow move (10 mm/s, real time) is stopped once the arm has left its start, so it stops short of its target.
/// </summary>
public class BridgeStopButtonTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    /// <summary>The last pose the controller reported (motion updates), for a test thread to read.</summary>
    private sealed class LivePose
    {
        private readonly Lock _gate = new();
        private Vector? _at;

        public LivePose(Robot robot) => robot.MotionUpdate += (_, e) =>
        {
            if (e.Position is Vector at)
            {
                lock (_gate)
                {
                    _at = at;
                }
            }
        };

        public Vector? At
        {
            get
            {
                lock (_gate)
                {
                    return _at;
                }
            }
        }
    }

    [ChromiumFact]
    public async Task Page_StopButton_StopsTheRunningMove_WhereTheArmIs_NothingAfterRuns()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { SimulationSpeed = 1 });
        await using Chromium browser = await Chromium.StartAsync(1280, 800);
        string program = "SpeedTo(10);\nMove(0,0,-200);\nMove(0,0,200);\n";
        await browser.NavigateAsync(new Uri(bridge.PageUri!, "/?name=Chromium&run=" + Uri.EscapeDataString(program)));
        Assert.Equal("open", await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "open", "closed"));
        Assert.False((await browser.EvaluateAsync("document.getElementById('stop').disabled")).GetBoolean());
        var live = new LivePose(bridge.Robot);
        Vector start = bridge.Robot.GetExecutedState().Position!.Value;
        await browser.EvaluateAsync("document.getElementById('send').click()");
        await Eventually.TrueAsync(() => live.At is Vector p && start.Z - p.Z > 5, "the arm to leave its start", Long);

        await browser.EvaluateAsync("document.getElementById('stop').click()");
        Assert.Equal("stopped", await browser.WaitForAsync("document.body ? document.body.dataset.state : ''", "stopped", "error", "done", "closed"));
        // The stop's control event and the failure of the move under way (reported once the arm has stopped) reach the page in either order.
        // Either one sets the state "stopped", so both are waited for before the page is read.
        Assert.Equal("1", await browser.WaitForAsync("String(document.querySelectorAll('#events li.ev-action-failed').length)", "1"));
        Assert.Equal("1", await browser.WaitForAsync("String(document.querySelectorAll('#events li.ev-control').length)", "1"));
        await browser.EvaluateAsync("new Promise(r => requestAnimationFrame(() => r(0)))");
        byte[] png = await browser.ScreenshotAsync();
        await File.WriteAllBytesAsync(Path.Combine(AppContext.BaseDirectory, "bridge-stop.png"), png);

        JsonElement shown = await browser.EvaluateAsync("JSON.parse(JSON.stringify({ names: [...document.querySelectorAll('#events li .name')].map(n => n.textContent), " +
            "failed: [...document.querySelectorAll('#events li.ev-action-failed')].map(n => n.textContent), " +
            "control: [...document.querySelectorAll('#events li.ev-control')].map(n => n.textContent), status: document.getElementById('statusText').textContent, " +
            "pending: document.getElementById('rPend').textContent }))");
        Assert.Equal("Stopped", shown.GetProperty("status").GetString());
        // After Stop nothing is left to execute: the move under way failed and the one after it was cancelled (it said "2" before).
        Assert.Equal("0 (stopped; 1 cancelled)", shown.GetProperty("pending").GetString());
        string failed = Assert.Single(shown.GetProperty("failed").EnumerateArray()).GetString()!;
        Assert.Contains("stopped by the user (Robot.Stop)", failed, StringComparison.Ordinal);
        Assert.Contains("(stopped)", failed, StringComparison.Ordinal);
        Assert.Contains("stop", Assert.Single(shown.GetProperty("control").EnumerateArray()).GetString()!, StringComparison.Ordinal);

        // The arm stopped part-way down and the move back up never ran.
        Vector at = bridge.Robot.GetExecutedState().Position!.Value;
        Assert.True(start.Z - at.Z > 5 && start.Z - at.Z < 150, $"the arm stopped at {at}, from {start}");
        await Task.Delay(300);
        Assert.True(Vector.Distance(live.At!.Value, at) < 0.01, $"the controller reports {live.At}, the robot stopped at {at}");
        Assert.Equal(1, shown.GetProperty("names").EnumerateArray().Count(n => n.GetString() == "action-executed")); // SpeedTo only
        Assert.True(png.Length > 10_000 && png[1] == 'P' && png[2] == 'N' && png[3] == 'G', "the screenshot is a PNG with content");
    }

    [Fact]
    public async Task PauseAndResumeMessages_HoldAndGoOn_EveryClientIsTold()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { SimulationSpeed = 1 });
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        var live = new LivePose(bridge.Robot);
        Vector start = bridge.Robot.GetExecutedState().Position!.Value;
        await client.SendAsync("SpeedTo(10); Move(0,0,-60);");
        await Eventually.TrueAsync(() => live.At is Vector p && start.Z - p.Z > 5, "the arm to leave its start", Long);

        await client.SendAsync(" #Pause ");
        JsonElement paused = (await client.ReceiveUntilAsync(e => e.Event() == "control"))[^1];
        Assert.Equal("{\"event\":\"control\",\"command\":\"pause\",\"user\":\"GH\"}", paused.GetRawText());
        Assert.Equal(ConnectionState.Stopped, bridge.Robot.ConnectionState);
        await client.SendAsync("#pause");
        JsonElement again = (await client.ReceiveUntilAsync(e => e.Event() == "error"))[^1];
        Assert.Equal("control", again.GetProperty("kind").GetString());
        Assert.StartsWith("#pause was not done: The robot is already stopped (Paused by the user", again.GetProperty("message").GetString(), StringComparison.Ordinal);

        await client.SendAsync("#resume");
        Assert.Equal("resume", ((await client.ReceiveUntilAsync(e => e.Event() == "control"))[^1]).GetProperty("command").GetString());
        await bridge.Robot.WaitForCompletionAsync().WaitAsync(Long);
        Assert.True(bridge.Robot.GetExecutedState().Position!.Value.IsSimilar(start + new Vector(0, 0, -60), 1e-2));
    }
}
