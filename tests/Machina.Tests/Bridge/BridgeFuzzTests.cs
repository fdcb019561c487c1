using System.Net;
using System.Net.Sockets;
using System.Net.WebSockets;
using System.Text;
using System.Text.Json;
using Machina.Bridge;
using static Machina.Tests.Bridge.BridgeTestSupport;

namespace Machina.Tests.Bridge;

/// <summary>
/// Seeded random and mutated input for everything the bridge reads from a client: the instruction text of a message, the
/// HTTP request head, and raw WebSocket bytes. Only documented outcomes may come out; never an exception, a hang or a crash.
/// </summary>
public class BridgeFuzzTests
{
    private const int Seed = 20261123;

    private static readonly string[] Corpus =
    [
        "Message(\"Hello Robot!\");", "SpeedTo(100);", "MoveTo(400,300,500);", "Rotate(0,1,0,-90);", "Move(0,0,250);", "Wait(2000);",
        "AxesTo(0,0,0,0,90,0);", "Speed(10);", "AccelerationTo(500);", "Acceleration(-10);", "PrecisionTo(5);", "Precision(1);",
        "MotionMode(\"Joint\");", "MotionMode(\"Linear\");", "Coordinates(\"Local\");", "PushSettings();", "PopSettings();",
        "RotateTo(-1,0,0,0,1,0);", "TransformTo(400,300,500,-1,0,0,0,1,0);", "Transform(10,0,0,0,0,1,45);", "Axes(10,0,0,0,0,0);",
        "ArcMotionTo(450,350,500,500,300,500);", "ArcMotion(50,50,0,100,0,0);", "ExternalAxisTo(1,500);", "ExternalAxis(2,10);",
        "ArmAngleTo(30);", "Comment(\"a (b); c\");", "CustomCode(\"VAR num n := 1;\",True);",
        "DefineTool(\"pen\",0,0,100,1,0,0,0,1,0,1,0,0,50);", "AttachTool(\"pen\");", "DetachTool();", "WriteDigital(1,True);",
        "WriteAnalog(\"ao_2\",0.5);", "TemperatureTo(200,\"extruder\",False);", "ExtrusionRateTo(0.1);", "Extrude(True);",
        "Initialize();", "Terminate();", "Message(\"say \\\"hi\\\" // not a comment\");",
    ];

    private static readonly string[] Numbers =
        ["1e308", "-1e308", "NaN", "Infinity", "1e400", "-0", "0x10", "1,5", "", "9E9", "99999999999999999999", "4.9e-324", "True", "\"7\"", "1_000"];

    private static readonly string Alphabet = "();,\"\\/*\n\r\t .-+eE0123456789abcxyzMoveTo\u00e9\u2028\u0000\uFEFF\U0001F916";

    [Fact]
    public void FrameHandler_100000SeededFrames_AcceptedWhollyOrRejectedWithADocumentedError()
    {
        var random = new Random(Seed);
        var robot = Robot.Create("Fuzz", RobotType.ABB);
        var handler = new FrameHandler(robot, () => true);
        int issuedSoFar = 0;
        robot.ActionIssued += (_, _) => issuedSoFar++; // offline, raised on this thread before Do returns
        var seen = new Dictionary<string, int>();
        for (int i = 0; i < 100_000; i++)
        {
            if (i % 1000 == 0)
            {
                robot.ClearProgram(); // keep memory flat; the state carries on
            }
            string frame = MakeFrame(random);
            int before = issuedSoFar;
            FrameResult result;
            try
            {
                result = handler.Handle(frame);
            }
            catch (Exception e)
            {
                Assert.Fail($"Case {i} (seed {Seed}) threw {e.GetType().Name}: {e.Message}\nFrame: {JsonSerializer.Serialize(frame)}");
                throw;
            }
            int issued = issuedSoFar - before;
            string kind;
            if (result.Outcome == FrameOutcome.Accepted)
            {
                Assert.Null(result.Reply);
                Assert.False(FrameHandler.HoldsNoInstruction(frame));
                Assert.True(issued >= 1, $"case {i}: accepted but nothing issued");
                if (i % 8 == 0)
                {
                    Assert.Equal(Instructions.Parse(frame).Count, issued); // all of the frame (checked on a sample: reading it again costs as much as issuing it)
                }
                kind = "accepted";
            }
            else
            {
                Assert.Equal(FrameOutcome.Rejected, result.Outcome);
                Assert.Equal(0, issued); // none of it
                JsonElement reply = JsonDocument.Parse(result.Reply!).RootElement;
                Assert.Equal("error", reply.GetProperty("event").GetString());
                kind = reply.GetProperty("kind").GetString()!;
                Assert.Contains(kind, new[] { "parse", "refused", "empty" });
                if (kind == "empty")
                {
                    Assert.Empty(Instructions.Parse(frame)); // the quick emptiness check agrees with the reader
                }
                Assert.False(string.IsNullOrWhiteSpace(reply.GetProperty("message").GetString()));
                Assert.DoesNotContain('\n', result.Reply!); // one line, like every bridge message
            }
            seen[kind] = seen.GetValueOrDefault(kind) + 1;
        }
        // The generator reaches every outcome often enough for the run to mean something.
        Assert.All(new[] { "accepted", "parse", "refused", "empty" }, k => Assert.True(seen.GetValueOrDefault(k) >= 500, $"{k}: {seen.GetValueOrDefault(k)}"));
    }

    [Fact]
    public void HttpRequestHead_100000SeededHeads_ParsedOrRefusedWithAReason()
    {
        var random = new Random(Seed);
        const string valid = "GET /Bridge?name=GH&client=Grasshopper HTTP/1.1\r\nHost: 127.0.0.1:6999\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n" +
            "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n";
        int parsed = 0;
        for (int i = 0; i < 100_000; i++)
        {
            byte[] head = i % 10 == 0 ? RandomBytes(random, random.Next(0, 300)) : Encoding.Latin1.GetBytes(Mutate(random, valid, random.Next(1, 5)));
            HttpRequestHead? request = HttpRequestHead.TryParse(head, out string? error);
            if (request is null)
            {
                Assert.False(string.IsNullOrEmpty(error), $"case {i}: refused without a reason");
                continue;
            }
            parsed++;
            Assert.Null(error);
            Assert.StartsWith("/", request.Path, StringComparison.Ordinal);
            _ = request.QueryValue("name");
            _ = request.HasToken("Connection", "Upgrade");
            _ = HttpConnection.IsValidKey(request["Sec-WebSocket-Key"]);
        }
        Assert.InRange(parsed, 10_000, 90_000);
    }

    [Fact]
    public async Task Server_SeededFramesOverTheSocket_EveryFrameAnsweredAndTheBridgeKeepsServing()
    {
        await using BridgeServer bridge = await StartAsync(o => o with { MaxMessageBytes = 4096, SimulationSpeed = 1000 });
        await using TestClient client = await TestClient.ConnectAsync(bridge, "?name=Fuzz");
        var random = new Random(Seed);
        for (int i = 0; i < 400; i++)
        {
            int pick = random.Next(20);
            if (pick == 0)
            {
                await client.SendAsync(RandomBytes(random, random.Next(0, 64)), WebSocketMessageType.Binary);
                Assert.Equal("frame", (await NextAnswerAsync(client)).GetProperty("kind").GetString());
                continue;
            }
            string frame = pick == 1 ? string.Concat(Enumerable.Repeat("Move(1,0,0);", 400)) : MakeFrame(random);
            await client.SendAsync(frame);
            JsonElement answer = await NextAnswerAsync(client);
            switch (answer.GetProperty("event").GetString())
            {
                case "action-issued":
                    // Every action of the frame is announced, then nothing else is outstanding.
                    int expected = Instructions.Parse(frame).Count;
                    for (int k = 1; k < expected; k++)
                    {
                        Assert.Equal("action-issued", (await NextAnswerAsync(client)).GetProperty("event").GetString());
                    }
                    break;
                case "error":
                    Assert.Contains(answer.GetProperty("kind").GetString(), new[] { "parse", "refused", "empty", "frame" });
                    break;
                default:
                    Assert.Equal("controller-disconnected", answer.GetProperty("event").GetString());
                    break;
            }
        }
        Assert.Equal(1, bridge.ClientCount);
    }

    [Fact]
    public async Task Server_SeededGarbageAfterTheHandshake_ConnectionDroppedAndOthersServed()
    {
        await using BridgeServer bridge = await StartAsync();
        var random = new Random(Seed);
        for (int i = 0; i < 200; i++)
        {
            using var tcp = new TcpClient();
            using var timeout = new CancellationTokenSource(Limit);
            await tcp.ConnectAsync(IPAddress.Loopback, bridge.Port, timeout.Token);
            NetworkStream stream = tcp.GetStream();
            await stream.WriteAsync(Encoding.ASCII.GetBytes(
                "GET /Bridge HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n"), timeout.Token);
            byte[] garbage = RandomBytes(random, random.Next(1, 200));
            if (random.Next(2) == 0)
            {
                garbage[0] = (byte)(0x80 | random.Next(16)); // FIN and any opcode, so that the header is read further
            }
            await stream.WriteAsync(garbage, timeout.Token);
            tcp.Client.Shutdown(SocketShutdown.Send);
            var sink = new byte[4096];
            try
            {
                while (await stream.ReadAsync(sink, timeout.Token) > 0)
                {
                    // Read until the bridge closes this connection.
                }
            }
            catch (IOException)
            {
                // Reset by the bridge: also fine.
            }
        }
        await EventuallyAsync(() => bridge.ClientCount == 0, "every garbage connection to be dropped");
        await using TestClient client = await TestClient.ConnectAsync(bridge);
        await client.SendAsync("SpeedTo(10);");
        Assert.Equal("action-issued", (await client.ReceiveAsync()).GetProperty("event").GetString());
    }

    /// <summary>The next message that answers a frame: action-issued, error or controller-disconnected (others are progress).</summary>
    private static async Task<JsonElement> NextAnswerAsync(TestClient client)
    {
        while (true)
        {
            JsonElement e = await client.ReceiveAsync();
            if (e.GetProperty("event").GetString() is "action-issued" or "error" or "controller-disconnected")
            {
                return e;
            }
        }
    }

    /// <summary>One to six corpus statements with random separators, then up to four mutations; sometimes pure noise.</summary>
    private static string MakeFrame(Random random)
    {
        int pick = random.Next(100);
        if (pick < 5)
        {
            return new string([.. Enumerable.Range(0, random.Next(0, 40)).Select(_ => Alphabet[random.Next(Alphabet.Length)])]);
        }
        if (pick < 8)
        {
            return new[] { "", " ", ";", ";;", "// x", "\n\n", "/* */" }[random.Next(7)];
        }
        var sb = new StringBuilder();
        int count = random.Next(1, 7);
        for (int i = 0; i < count; i++)
        {
            sb.Append(Corpus[random.Next(Corpus.Length)]);
            sb.Append(new[] { "", " ", "\n", "\r\n", " // note\n", "\t" }[random.Next(6)]);
        }
        return Mutate(random, sb.ToString(), random.Next(0, 5));
    }

    private static string Mutate(Random random, string text, int mutations)
    {
        var sb = new StringBuilder(text);
        for (int m = 0; m < mutations && sb.Length > 0; m++)
        {
            int at = random.Next(sb.Length);
            switch (random.Next(7))
            {
                case 0:
                    sb.Insert(at, Alphabet[random.Next(Alphabet.Length)]);
                    break;
                case 1:
                    sb.Remove(at, Math.Min(sb.Length - at, random.Next(1, 6)));
                    break;
                case 2:
                    sb.Insert(at, sb.ToString(at, Math.Min(sb.Length - at, random.Next(1, 20))));
                    break;
                case 3:
                    sb.Length = at;
                    break;
                case 4:
                    // Replace a run of digits with an extreme or malformed number.
                    int start = at;
                    while (start < sb.Length && !char.IsAsciiDigit(sb[start]))
                    {
                        start++;
                    }
                    int end = start;
                    while (end < sb.Length && (char.IsAsciiDigit(sb[end]) || sb[end] == '.'))
                    {
                        end++;
                    }
                    if (end > start)
                    {
                        sb.Remove(start, end - start).Insert(start, Numbers[random.Next(Numbers.Length)]);
                    }
                    break;
                case 5:
                    sb[at] = char.IsUpper(sb[at]) ? char.ToLowerInvariant(sb[at]) : char.ToUpperInvariant(sb[at]);
                    break;
                default:
                    sb[at] = (char)random.Next(0, 0x80);
                    break;
            }
        }
        return sb.ToString();
    }

    private static byte[] RandomBytes(Random random, int length)
    {
        byte[] bytes = new byte[length];
        random.NextBytes(bytes);
        return bytes;
    }
}
