using System.Text.Json;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

public class BridgeServerTests
{
    [Fact]
    public async Task Dump_Transcript()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient gh = await TestClient.ConnectAsync(bridge);
        bridge.VirtualAbb!.StopAnswering();
        foreach (string frame in HelloRobot)
        {
            await gh.SendAsync(frame);
        }
        var issued = await gh.ReceiveUntilAsync(e => e.Event() == "action-issued" && e.Id() == 7);
        bridge.VirtualAbb!.ResumeAnswering();
        var rest = await gh.ReceiveUntilAsync(e => e.Event() == "action-executed" && e.Id() == 7);
        File.WriteAllLines("/tmp/transcript.txt", issued.Concat(rest).Select(e => e.GetRawText()));
    }
}
