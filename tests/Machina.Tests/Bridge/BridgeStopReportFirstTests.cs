using System.Text.Json;
using Machina.Bridge;
using Machina.Tests.Stopping;

namespace Machina.Tests.Bridge;

/// <summary>
/// The bridge's #stop when the ABB driver task's report of the stopped move (<c>$26 id 4;</c>) reaches the host before the monitor
/// task's answer (<c>$28 3;</c>), played by <see cref="ScriptedAbbController"/> (see <see cref="AbbStopReportFirstTests"/>): every
/// client is told the stop (control) and the failure. Before session 36 Robot.Stop waited 10 s for the unread answer and the sender
/// got an error of kind control instead, so the page's Stop button never showed the stop.
/// </summary>
public class BridgeStopReportFirstTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task BridgeStop_DriverReportsTheStoppedMoveBeforeTheMonitorAnswers_EveryClientIsToldTheStopAndTheFailure()
    {
        await using var controller = ScriptedAbbController.Start();
        Task accepting = controller.AcceptAsync();
        await using BridgeServer bridge = await BridgeTestSupport.StartAsync(o => o with { ControllerHost = "127.0.0.1", ControllerPort = controller.Port });
        await accepting.WaitAsync(Long);
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        await client.SendAsync(AbbStopReportFirstTests.Program);
        await controller.ReadDriverUntilAsync("@3 10 ");
        await controller.WriteDriverAsync("@1 4;");

        await client.SendAsync("#stop");
        await controller.StopReportFirstAsync(2);

        // The page's Stop button waits for both: the failure of the move under way and the stop's control event (not an error).
        List<JsonElement> seen = await client.ReceiveUntilAsync(e => e.Event() is "control" or "error");
        if (!seen.Exists(e => e.Event() == "action-failed"))
        {
            seen.AddRange(await client.ReceiveUntilAsync(e => e.Event() == "action-failed"));
        }
        Assert.Equal("{\"event\":\"control\",\"command\":\"stop\",\"user\":\"GH\"}", seen.Single(e => e.Event() is "control" or "error").GetRawText());
        JsonElement failure = seen.Single(e => e.Event() == "action-failed");
        Assert.Equal("stopped", failure.GetProperty("code").GetString());
        Assert.Equal(2, failure.GetProperty("id").GetInt32());
    }
}
