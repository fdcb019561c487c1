using System.Text.Json;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

/// <summary>
/// The tool instructions that Processing's and Python's clients send under names Machina never had (spec bridge §2), with their
/// formatting slips, are issued as the Machina instructions they mean, through the WebSocket path.
/// </summary>
public class BridgeAliasTests
{
    [Fact]
    public async Task ClientToolAliases_AreIssuedAsDefineAttachAndDetachTool()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge, "?name=Processing");
        (string Sent, string Issued)[] cases =
        [
            // Processing: Tool.Create with an empty argument before the weight; Detach() without a semicolon.
            ("Tool.Create(\"pen\",0.0,0.0,100.0,1.0,0.0,0.0,0.0,1.0,0.0,,0.5,0.0,0.0,50.0);", "DefineTool(\"pen\",0,0,100,1,0,0,0,1,0,0.5,0,0,50);"),
            ("Attach(\"pen\");", "AttachTool(\"pen\");"),
            ("Detach()", "DetachTool();"),
            // Python: Tool.create with a trailing comma.
            ("Tool.create(\"brush\",0,0,50,1,0,0,0,1,0,1,0,0,20,);", "DefineTool(\"brush\",0,0,50,1,0,0,0,1,0,1,0,0,20);"),
            (" Attach(\"brush\") ", "AttachTool(\"brush\");"),
            // Text that only looks like an alias inside a string is left alone.
            ("Message(\"Attach(me)\");", "Message(\"Attach(me)\");"),
        ];

        var issued = new List<string>();
        foreach ((string sent, _) in cases)
        {
            await client.SendAsync(sent);
            List<JsonElement> events = await client.ReceiveUntilAsync(e => e.Event() is "action-issued" or "error");
            issued.Add(events[^1].Event() == "error" ? "error: " + events[^1].GetRawText() : events[^1].GetProperty("last").GetString()!);
        }

        Assert.Equal(cases.Select(c => c.Issued), issued);
        Assert.Equal("brush", bridge.Robot.GetIssuedState().Tool?.Name);
    }

    [Fact]
    public async Task RemovedSettings_RotationAndJointSpeed_GetAParseErrorAndIssueNothing()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge, "?name=Processing");

        await client.SendAsync("RotationSpeed(10);");
        JsonElement error = (await client.ReceiveUntilAsync(e => e.Event() is "action-issued" or "error"))[^1];

        Assert.Equal("error", error.Event());
        Assert.Equal("parse", error.GetProperty("kind").GetString());
        Assert.Null(bridge.Robot.GetIssuedState().LastAction);
    }
}
