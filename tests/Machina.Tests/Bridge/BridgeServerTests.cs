using System.Net;
using System.Net.Sockets;
using System.Net.WebSockets;
using System.Text;
using System.Text.Json;
using Machina.Bridge;
using Machina.Simulation;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

public class BridgeServerTests
{
    private static readonly string[] IssuedKeys = ["event", "last", "id", "pos", "ori", "quat", "axes", "extax", "conf"];
    private static readonly string[] ReleasedKeys = ["event", "last", "id", "pend", "pos", "ori", "quat", "axes", "extax", "conf"];
    private static readonly string[] ExecutedKeys = ["event", "last", "id", "pendDev", "pendTot", "pos", "ori", "quat", "axes", "extax", "conf"];

    /// <summary>The spec's §7 T2 example, byte for byte.</summary>
    private const string ExecutedMoveLine =
        "{\"event\":\"action-executed\",\"last\":\"Move(0,0,250);\",\"id\":5,\"pendDev\":2,\"pendTot\":2,\"pos\":[400,300,750],\"ori\":[0,0,-1,0,1,0],\"quat\":[0.7071,0,0.7071,0],\"axes\":[43.332,-0.672,18.367,-107.858,46.134,114.935],\"extax\":null,\"conf\":null}";

    [Fact]
    public async Task Grasshopper_OneFramePerAction_EventsInOrderWithTheFieldsClientsRead()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient gh = await TestClient.ConnectAsync(bridge, "?name=GH&client=Grasshopper");
        await RunHelloRobotAsync(bridge, gh, HelloRobot); // Send.cs: one frame per action
    }

    [Fact]
    public async Task WholeProgram_OneFrame_EventsInOrderWithTheFieldsClientsRead()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge, "?name=Processing");
        await RunHelloRobotAsync(bridge, client, [string.Join("\n", HelloRobot)]);
    }

    /// <summary>
    /// Sends the frames while the controller holds its acknowledgements (so that the counts do not depend on timing), then
    /// lets it execute, and checks every event: order, field names in order, values (spec §3 and §7 T2).
    /// </summary>
    private static async Task RunHelloRobotAsync(BridgeServer bridge, TestClient client, string[] frames)
    {
        var controller = (Machina.Simulation.VirtualAbbController)bridge.Simulator!;
        controller.StopAnswering();
        foreach (string frame in frames)
        {
            await client.SendAsync(frame);
        }
        List<JsonElement> all = await client.ReceiveUntilAsync(e => e.Event() == "action-released" && e.Id() == 7);
        Assert.Equal(14, all.Count);
        controller.ResumeAnswering();
        all.AddRange(await client.ReceiveUntilAsync(e => e.Event() == "action-executed" && e.Id() == 7));
        Assert.Equal(21, all.Count);

        List<JsonElement> issued = [.. all.Where(e => e.Event() == "action-issued")];
        List<JsonElement> released = [.. all.Where(e => e.Event() == "action-released")];
        List<JsonElement> executed = [.. all.Where(e => e.Event() == "action-executed")];
        Assert.Equal(HelloRobot, issued.Select(e => e.GetProperty("last").GetString()));
        Assert.Equal(HelloRobot, executed.Select(e => e.GetProperty("last").GetString()));
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], issued.Select(e => e.Id()));
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], released.Select(e => e.Id()));
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed.Select(e => e.Id()));
        for (int id = 1; id <= 7; id++)
        {
            int i = all.FindIndex(e => e.Event() == "action-issued" && e.Id() == id);
            int r = all.FindIndex(e => e.Event() == "action-released" && e.Id() == id);
            int x = all.FindIndex(e => e.Event() == "action-executed" && e.Id() == id);
            Assert.True(i < r && r < x, $"action {id}: issued at {i}, released at {r}, executed at {x}");
        }
        AssertHelloRobotFields(issued, released, executed);
    }

    /// <summary>Checks what Grasshopper, Dynamo and Processing read: field names in order, integer ids, counts, poses (spec §3, §7 T2).</summary>
    private static void AssertHelloRobotFields(List<JsonElement> issued, List<JsonElement> released, List<JsonElement> executed)
    {
        Assert.All(issued, e => Assert.Equal(IssuedKeys, e.Keys()));
        Assert.All(released, e => Assert.Equal(ReleasedKeys, e.Keys()));
        Assert.All(executed, e => Assert.Equal(ExecutedKeys, e.Keys()));
        Assert.All(issued.Concat(released).Concat(executed), e => Assert.Equal(JsonValueKind.Number, e.GetProperty("id").ValueKind));
        Assert.All(issued.Concat(released).Concat(executed), e => Assert.Equal(JsonValueKind.Null, e.GetProperty("conf").ValueKind));
        Assert.All(released, e => Assert.Equal(JsonValueKind.Number, e.GetProperty("pend").ValueKind));

        Assert.Equal([6, 5, 4, 3, 2, 1, 0], executed.Select(e => e.GetProperty("pendTot").GetInt32()));
        Assert.Equal([6, 5, 4, 3, 2, 1, 0], executed.Select(e => e.GetProperty("pendDev").GetInt32()));
        // The virtual controller (an IRB 1200-5/0.9) starts where its model puts the ABB home joints, tool down.
        Assert.Equal("[451,0,807.1]", executed[0].Raw("pos"));
        Assert.Equal("[-1,0,0,0,1,0]", executed[0].Raw("ori"));
        Assert.Equal("[0,0,1,0]", executed[0].Raw("quat"));
        Assert.Equal("[0,0,0,0,90,0]", executed[0].Raw("axes"));
        Assert.Equal("[451,0,807.1]", executed[1].Raw("pos"));
        Assert.Equal("[400,300,500]", executed[2].Raw("pos"));
        // The robot knows the controller's arm, so every pose has its joints (inverse kinematics) and every joint move its pose.
        Assert.Equal("[36.87,15.7,22.876,0,51.424,36.87]", executed[2].Raw("axes"));
        Assert.Equal("[0,0,-1,0,1,0]", executed[3].Raw("ori"));
        Assert.Equal("[0.7071,0,0.7071,0]", executed[3].Raw("quat"));
        Assert.Equal(ExecutedMoveLine, executed[4].GetRawText());
        Assert.Equal("[400,300,750]", executed[5].Raw("pos"));
        Assert.Equal("[451,0,807.1]", executed[6].Raw("pos"));
        Assert.Equal("[-1,0,0,0,1,0]", executed[6].Raw("ori"));
        Assert.Equal("[0,0,1,0]", executed[6].Raw("quat"));
        Assert.Equal("[0,0,0,0,90,0]", executed[6].Raw("axes"));

        // Difference from the original (docs/bridge.md): action-issued and action-released carry the action's own target.
        Assert.Equal("[400,300,500]", issued[2].Raw("pos"));
        Assert.Equal("[400,300,750]", issued[4].Raw("pos"));
        Assert.Equal("[0.7071,0,0.7071,0]", released[3].Raw("quat"));
        Assert.Equal("[451,0,807.1]", issued[6].Raw("pos"));
        Assert.Equal("[0,0,0,0,90,0]", issued[6].Raw("axes"));
    }

    /// <summary>
    /// Issue 24: a page's Hello Robot ends with AxesTo, and a Python client's MoveTo that followed was refused ("orientation is
    /// not known"). The robot learns the embedded controller's arm when it connects (the bridge names no model), so the joint
    /// move has a pose and the MoveTo runs.
    /// </summary>
    [Fact]
    public async Task EmbeddedController_GivesTheRobotItsArm_SoAMoveToAfterAnAxesToRuns()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge);

        Assert.Equal("ABB IRB 1200-5/0.9", bridge.Robot.Model?.ToString());
        await client.SendAsync("AxesTo(0,0,0,0,90,0);");
        await client.SendAsync("MoveTo(400,300,500);");
        var executed = new List<string>();
        while (executed.Count < 2)
        {
            string text = await client.ReceiveTextAsync() ?? throw new InvalidOperationException("closed");
            Assert.DoesNotContain("refused", text, StringComparison.OrdinalIgnoreCase);
            if (text.Contains("\"action-executed\"", StringComparison.Ordinal))
            {
                executed.Add(text);
            }
        }
        Assert.Contains("\"last\":\"MoveTo(400,300,500);\"", executed[1], StringComparison.Ordinal);
        Assert.Contains("\"pos\":[400,300,500]", executed[1], StringComparison.Ordinal);
    }

    [Fact]
    public async Task MotionUpdate_WhileMoving_OriginalFieldsAndOnlyWhenThePoseChanged()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        await client.SendAsync("MoveTo(400,300,500);");
        var updates = new List<string>();
        while (updates.Count == 0 || !updates[^1].Contains("\"pos\":[400,300,500]", StringComparison.Ordinal))
        {
            string text = await client.ReceiveTextAsync() ?? throw new InvalidOperationException("closed");
            if (text.Contains("\"motion-update\"", StringComparison.Ordinal))
            {
                updates.Add(text);
            }
        }
        JsonElement last = JsonDocument.Parse(updates[^1]).RootElement;
        Assert.Equal(["event", "pos", "ori", "quat", "axes", "extax", "conf"], last.Keys());
        Assert.Equal("[-1,0,0,0,1,0]", last.Raw("ori"));
        Assert.Equal("[0,0,1,0]", last.Raw("quat"));
        Assert.Equal(JsonValueKind.Array, last.GetProperty("axes").ValueKind);
        Assert.Equal("null", last.Raw("conf"));
        for (int i = 1; i < updates.Count; i++)
        {
            Assert.NotEqual(updates[i - 1], updates[i]); // a report that changed nothing is not sent again
        }
    }

    [Fact]
    public async Task Python_NewConnectionPerStatement_EveryStatementGetsOneAnswer()
    {
        await using BridgeServer bridge = await StartAsync();
        // machinaRobot.py formats Python floats and waits for exactly one message per connection.
        (string Sent, string Event, string Detail)[] cases =
        [
            ("MoveTo(400.0,300.0,500.0);", "action-issued", "MoveTo(400,300,500);"),
            ("Move(0.0,0.0,25.5);", "action-issued", "Move(0,0,25.5);"),
            ("Wait(2000.5);", "error", "parse"),
            ("Detach()", "action-issued", "DetachTool();"),
            ("AxesTo(0,0,0,0,90,0);", "action-issued", "AxesTo(0,0,0,0,90,0);"),
            ("AttachTool(\"ghost\");", "error", "refused"),
        ];
        foreach ((string sent, string expectedEvent, string detail) in cases)
        {
            await using TestClient python = await TestClient.ConnectAsync(bridge, "");
            await python.SendAsync(sent);
            JsonElement answer = await python.ReceiveAsync();
            Assert.Equal(expectedEvent, answer.Event());
            Assert.Equal(detail, answer.GetProperty(expectedEvent == "error" ? "kind" : "last").GetString());
            // The statement's later events (its execution) go to this connection, not to the next one's first answer.
            await bridge.Robot.WaitForCompletionAsync().WaitAsync(Limit);
            await bridge.Robot.FlushEventsAsync().WaitAsync(Limit);
            await python.CloseAsync();
        }
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bridge.Robot.GetIssuedState().Axes);
        // The robot knows the embedded controller's arm (an IRB 1200-5/0.9), so the joint move has a pose: its home, tool down.
        Assert.True(bridge.Robot.GetIssuedState().Position!.Value.IsSimilar(new Vector(451, 0, 807.1), 0.05), $"{bridge.Robot.GetIssuedState().Position}");
    }

    [Fact]
    public async Task RefusedStatement_NothingIssued_OnlySenderGetsErrorEvent()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient sender = await TestClient.ConnectAsync(bridge, "?name=A");
        await using TestClient other = await TestClient.ConnectAsync(bridge, "?name=B");
        await EventuallyAsync(() => bridge.ClientCount == 2, "both clients to be registered");

        await sender.SendAsync("SpeedTo(50); AxesTo(0,0,0,0,90,0); AttachTool(\"ghost\");");
        JsonElement error = await sender.ReceiveAsync();
        Assert.Equal(["event", "kind", "message", "instruction"], error.Keys());
        Assert.Equal("error", error.Event());
        Assert.Equal("refused", error.GetProperty("kind").GetString());
        Assert.Equal("AttachTool(\"ghost\");", error.GetProperty("instruction").GetString());
        Assert.StartsWith("Cannot apply \"AttachTool(\"ghost\");\": no tool named \"ghost\" is defined", error.GetProperty("message").GetString(), StringComparison.Ordinal);

        // Nothing of the refused frame was issued, and no id was used: the next action is number 1, and both clients see it.
        await other.SendAsync("SpeedTo(20);");
        foreach (TestClient client in new[] { sender, other })
        {
            JsonElement next = await client.ReceiveAsync();
            Assert.Equal("action-issued", next.Event());
            Assert.Equal(1, next.Id());
            Assert.Equal("SpeedTo(20);", next.GetProperty("last").GetString());
        }
        Assert.Equal(20, bridge.Robot.GetIssuedState().Speed);
    }

    [Fact]
    public async Task MalformedText_ErrorEventWithLineAndColumn()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        await client.SendAsync("MoveTo(400,300,500);\nMoveTo(400,,500);");
        JsonElement error = await client.ReceiveAsync();
        Assert.Equal("parse", error.GetProperty("kind").GetString());
        Assert.Equal(2, error.GetProperty("line").GetInt32());
        Assert.Equal(12, error.GetProperty("column").GetInt32()); // the empty value between the two commas
        Assert.Equal("Line 2, column 12: a value is missing in MoveTo(...).", error.GetProperty("message").GetString());
        Assert.Empty(bridge.Robot.GetPendingActions());
    }

    [Fact]
    public async Task EmptyBinaryAndOversizedMessages_ErrorEvents_ConnectionKeepsWorking()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { MaxMessageBytes = 1024 });
        await using TestClient client = await TestClient.ConnectAsync(bridge);

        await client.SendAsync("  ;; // only a comment\n");
        Assert.Equal("empty", (await client.ReceiveAsync()).GetProperty("kind").GetString());
        await client.SendAsync([1, 2, 3], WebSocketMessageType.Binary);
        JsonElement binary = await client.ReceiveAsync();
        Assert.Equal("frame", binary.GetProperty("kind").GetString());
        Assert.Contains("Binary", binary.GetProperty("message").GetString(), StringComparison.Ordinal);
        await client.SendAsync(string.Concat(Enumerable.Repeat("Move(1,0,0);", 100))); // 1200 bytes
        JsonElement large = await client.ReceiveAsync();
        Assert.Equal("frame", large.GetProperty("kind").GetString());
        Assert.Contains("1024 bytes", large.GetProperty("message").GetString(), StringComparison.Ordinal);

        await client.SendAsync("SpeedTo(10);");
        JsonElement issued = await client.ReceiveAsync();
        Assert.Equal("action-issued", issued.Event());
        Assert.Equal(1, issued.Id());
    }

    [Fact]
    public async Task InvalidUtf8Text_ConnectionClosedAsInvalidPayload_OthersServed()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient bad = await TestClient.ConnectAsync(bridge, "?name=Bad");
        await bad.SendAsync([0x4D, 0xC3, 0x28], WebSocketMessageType.Text); // "M" then a broken two-byte sequence
        string? text;
        while ((text = await bad.ReceiveTextAsync()) is not null)
        {
            Assert.StartsWith("{\"event\":\"motion-update\"", text, StringComparison.Ordinal);   // a live pose may come first
        }
        Assert.Equal(WebSocketCloseStatus.InvalidPayloadData, bad.CloseStatus);
        await using TestClient good = await TestClient.ConnectAsync(bridge);
        await good.SendAsync("SpeedTo(10);");
        Assert.Equal("action-issued", (await good.ReceiveAsync()).Event());
    }

    [Fact]
    public async Task GrasshopperInstructionsTheOriginalRefused_CustomCodeAndArmAngleTo_Issued()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient gh = await TestClient.ConnectAsync(bridge);
        await gh.SendAsync("CustomCode(\"VAR num n := 1;\",True);");
        Assert.Equal("CustomCode(\"VAR num n := 1;\",True);", (await gh.ReceiveAsync()).GetProperty("last").GetString());
        await gh.SendAsync("ArmAngleTo(30);");
        Assert.Equal("ArmAngleTo(30);", (await gh.ReceiveUntilAsync(e => e.Event() == "action-issued" && e.Id() == 2))[^1].GetProperty("last").GetString());
    }

    [Fact]
    public async Task ClientLeaves_OthersGetClientDisconnectedWithItsName()
    {
        await using BridgeServer bridge = await StartAsync();
        await using TestClient stays = await TestClient.ConnectAsync(bridge, "?name=Stays");
        TestClient leaves = await TestClient.ConnectAsync(bridge, "?name=Dynamo%20BIM&client=Dynamo");
        await EventuallyAsync(() => bridge.ClientCount == 2, "both clients to be registered");
        await leaves.CloseAsync();
        await leaves.DisposeAsync();

        JsonElement e = await stays.ReceiveAsync();
        Assert.Equal("{\"event\":\"client-disconnected\",\"user\":\"Dynamo BIM\"}", e.GetRawText());
        await EventuallyAsync(() => bridge.ClientCount == 1, "the client to be removed");
    }

    [Fact]
    public async Task ControllerLost_EveryClientGetsControllerDisconnectedOncePerFrame()
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        await using BridgeServer bridge = await StartAsync(o => o with { ControllerHost = "127.0.0.1", ControllerPort = controller.Port });
        Assert.Null(bridge.SimulatorPort);
        await using TestClient a = await TestClient.ConnectAsync(bridge, "?name=A");
        await using TestClient b = await TestClient.ConnectAsync(bridge, "?name=B");
        await EventuallyAsync(() => bridge.ClientCount == 2, "both clients to be registered");
        await controller.DisposeAsync();
        await EventuallyAsync(() => !bridge.Robot.IsConnected, "the bridge to notice the lost controller");

        await a.SendAsync(string.Join("", HelloRobot));
        foreach (TestClient client in new[] { a, b })
        {
            Assert.Equal("{\"event\":\"controller-disconnected\"}", (await client.ReceiveAsync()).GetRawText());
        }
        Assert.Empty(bridge.Robot.GetPendingActions()); // the frame was dropped, not queued
        Assert.False(a.HasPendingMessage());
    }

    [Fact]
    public async Task Http_PageErrorsAndUpgradeRequired()
    {
        await using BridgeServer bridge = await StartAsync();
        Assert.NotEqual(0, bridge.Port);
        Assert.Equal($"ws://127.0.0.1:{bridge.Port}/Bridge", bridge.WebSocketUri!.ToString());

        string page = await RawRequestAsync(bridge, $"GET / HTTP/1.1\r\nHost: 127.0.0.1:{bridge.Port}\r\n\r\n");
        Assert.StartsWith("HTTP/1.1 200 OK\r\n", page, StringComparison.Ordinal);
        Assert.Contains("Content-Type: text/html; charset=utf-8\r\n", page, StringComparison.Ordinal);
        Assert.Contains("const BRIDGE_PATH = \"/Bridge\";", page, StringComparison.Ordinal);
        Assert.DoesNotContain("__BRIDGE_PATH__", page, StringComparison.Ordinal);

        string head = await RawRequestAsync(bridge, "HEAD / HTTP/1.1\r\nHost: x\r\n\r\n");
        int length = int.Parse(page[(page.IndexOf("Content-Length: ", StringComparison.Ordinal) + 16)..page.IndexOf("\r\nCache", StringComparison.Ordinal)], System.Globalization.CultureInfo.InvariantCulture);
        Assert.Equal(page.Length - page.IndexOf("\r\n\r\n", StringComparison.Ordinal) - 4, length);
        Assert.Contains($"Content-Length: {length}\r\n", head, StringComparison.Ordinal);
        Assert.EndsWith("\r\n\r\n", head, StringComparison.Ordinal); // no body
        Assert.StartsWith("HTTP/1.1 404 ", await RawRequestAsync(bridge, "GET /favicon.ico HTTP/1.1\r\nHost: x\r\n\r\n"), StringComparison.Ordinal);
        Assert.StartsWith("HTTP/1.1 405 ", await RawRequestAsync(bridge, "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n\r\n"), StringComparison.Ordinal);
        Assert.StartsWith("HTTP/1.1 426 ", await RawRequestAsync(bridge, "GET /Bridge HTTP/1.1\r\nHost: x\r\n\r\n"), StringComparison.Ordinal);
        Assert.StartsWith("HTTP/1.1 400 ", await RawRequestAsync(bridge, "HELLO\r\n\r\n"), StringComparison.Ordinal);
        Assert.StartsWith("HTTP/1.1 400 ", await RawRequestAsync(bridge,
            "GET /Bridge HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: short\r\n\r\n"), StringComparison.Ordinal);
        Assert.StartsWith("HTTP/1.1 431 ", await RawRequestAsync(bridge, "GET / HTTP/1.1\r\nX: " + new string('a', 20_000) + "\r\n\r\n"), StringComparison.Ordinal);
        string upgraded = await RawRequestAsync(bridge,
            "GET /bridge/?name=raw HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: keep-alive, Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n",
            untilBlankLine: true);
        Assert.Equal("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=\r\n\r\n", upgraded);
    }

    [Fact]
    public async Task BrowserOrigin_OwnPageAndAllowedOriginsOnly()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { AllowedOrigins = ["http://localhost:8080"] });
        string own = $"http://127.0.0.1:{bridge.Port}";
        foreach ((string origin, int speed) in new[] { (own, 10), ("http://localhost:8080", 20) })
        {
            await using TestClient ok = await TestClient.ConnectAsync(bridge, "", o => o.SetRequestHeader("Origin", origin));
            await ok.SendAsync($"SpeedTo({speed});");
            await ok.ReceiveUntilAsync(e => e.Event() == "action-issued" && e.GetProperty("last").GetString() == $"SpeedTo({speed});");
        }
        foreach (string origin in new[] { "http://evil.example", "null", $"http://evil.example:{bridge.Port}" })
        {
            await Assert.ThrowsAsync<WebSocketException>(() => TestClient.ConnectAsync(bridge, "", o => o.SetRequestHeader("Origin", origin)));
        }
    }

    [Fact]
    public async Task StopAsync_ClientsGetACloseFrame_RobotDisconnected()
    {
        BridgeServer bridge = await StartAsync();
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        await EventuallyAsync(() => bridge.ClientCount == 1, "the client to be registered");
        await bridge.StopAsync().WaitAsync(Limit);
        // The virtual controller's live poses may reach the client before the close frame; nothing else may.
        string? text;
        while ((text = await client.ReceiveTextAsync()) is not null)
        {
            Assert.StartsWith("{\"event\":\"motion-update\"", text, StringComparison.Ordinal);
        }
        Assert.Equal(WebSocketCloseStatus.EndpointUnavailable, client.CloseStatus);
        Assert.False(bridge.Robot.IsConnected);
        await bridge.StopAsync(); // twice is fine
        using var tcp = new TcpClient();
        await Assert.ThrowsAnyAsync<SocketException>(() => tcp.ConnectAsync(IPAddress.Loopback, bridge.Port));
    }

    [Fact]
    public async Task StopAsync_ClientNeverAnswersTheCloseFrame_DroppedAfterTheCloseTimeout()
    {
        BridgeServer bridge = await StartAsync();
        bridge.CloseTimeout = TimeSpan.FromMilliseconds(200);
        using var tcp = new TcpClient();
        await tcp.ConnectAsync(IPAddress.Loopback, bridge.Port);
        await tcp.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "GET /Bridge HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n"));
        await EventuallyAsync(() => bridge.ClientCount == 1, "the silent client to be registered");

        await bridge.StopAsync().WaitAsync(Limit); // the client reads nothing and never closes: the bridge drops it

        Assert.Equal(0, bridge.ClientCount);
        Assert.False(bridge.Robot.IsConnected);
    }

    [Fact]
    public async Task StopAsync_AfterAMoveTheVirtualControllerCannotRun_CompletesAndLogsTheFailure()
    {
        BridgeServer bridge = await StartAsync();
        var errors = new System.Collections.Concurrent.ConcurrentQueue<string>();
        bridge.Robot.Logger.Logged += (_, e) => { if (e.Level == LogLevel.ERROR) { errors.Enqueue(e.Message); } };
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        // 1 km away at 1e-9 mm/s: the controller refuses the target (outside reach) before it would try to time the motion, so
        // the failure is reported (issue 21) and the stop that follows must still complete.
        await client.SendAsync("SpeedTo(1e-9);MoveTo(1e6,0,0);");
        await client.ReceiveUntilAsync(e => e.Event() == "action-failed" && e.Id() == 2);
        await bridge.StopAsync().WaitAsync(Limit); // never throws, whatever state the virtual controller is in
        Assert.False(bridge.Robot.IsConnected);
        Assert.Contains(errors, m => m.StartsWith("The controller could not run action 2: Position outside reach", StringComparison.Ordinal));
        Assert.All(errors, m => Assert.Contains("The controller could not run", m, StringComparison.Ordinal));
    }

    [Fact]
    public async Task StartAsync_BrandWithoutVirtualController_ThrowsAndReleasesThePort()
    {
        var bridge = new BridgeServer(Options(o => o with { RobotFactory = null, Brand = RobotType.ZMORPH }));
        var e = await Assert.ThrowsAsync<NotSupportedException>(() => bridge.StartAsync());
        Assert.Contains("no virtual controller for ZMORPH", e.Message, StringComparison.Ordinal);
        int port = bridge.Port;
        var listener = new TcpListener(IPAddress.Loopback, port);
        listener.Start(); // the bridge let go of its port
        listener.Stop();
        await bridge.DisposeAsync();
    }

    [Fact]
    public void Options_Invalid_ThrowArgumentExceptionNamingTheSetting()
    {
        Assert.Equal("Path", Assert.ThrowsAny<ArgumentException>(() => new BridgeServer(new BridgeOptions { Path = "Bridge" })).ParamName);
        Assert.Equal("SimulationSpeed", Assert.ThrowsAny<ArgumentException>(() => new BridgeServer(new BridgeOptions { SimulationSpeed = 0 })).ParamName);
        Assert.Equal("ControllerPort", Assert.ThrowsAny<ArgumentException>(() => new BridgeServer(new BridgeOptions { ControllerPort = 70000 })).ParamName);
        Assert.Equal("ControllerHost", Assert.ThrowsAny<ArgumentException>(() => new BridgeServer(new BridgeOptions { ControllerHost = " " })).ParamName);
    }

    /// <summary>Sends raw bytes and reads the answer until the server closes (or, for a handshake, until the blank line).</summary>
    private static Task<string> RawRequestAsync(BridgeServer bridge, string request, bool untilBlankLine = false) =>
        RawHttp.RequestAsync(bridge.Port, request, untilBlankLine);
}
