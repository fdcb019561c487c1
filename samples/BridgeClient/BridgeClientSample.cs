// A client of the Machina Bridge that behaves like Machina for Grasshopper: it connects to the bridge's WebSocket, sends
// the paper's Hello Robot one action per message (exactly the text Grasshopper's Send component writes), and prints
// every event the bridge sends back as JSON: action-issued, action-released, action-executed, motion-update. Any
// program that speaks WebSockets (Python, Processing, a web page, Node) can do the same; this one uses only .NET's own
// ClientWebSocket and JSON reader.
//
// Usage:
//   dotnet run --project samples/BridgeClient                                  starts a bridge with a virtual ABB robot inside this program
//   dotnet run --project samples/BridgeClient -- --url ws://127.0.0.1:6999/Bridge   connects to a running `machina bridge` instead
//   [--speed-factor F]   how much faster than real time the virtual robot moves (default 4; the bridge started here only)
using System.Globalization;
using System.Net;
using System.Net.WebSockets;
using System.Text;
using System.Text.Json;
using Machina.Bridge;

namespace Machina.Samples;

/// <summary>The bridge client sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class BridgeClientSample
{
    /// <summary>What Grasshopper's Send writes for the paper's Hello Robot: one message per action.</summary>
    private static readonly string[] HelloRobot =
    [
        "Message(\"Hello Robot!\");",
        "SpeedTo(100);",
        "MoveTo(400,300,500);",
        "Rotate(0,1,0,-90);",
        "Move(0,0,250);",
        "Wait(2000);",
        "AxesTo(0,0,0,0,90,0);",
    ];

    /// <summary>What the original Processing client sends to set the rotation speed: not a Machina instruction (<c>Speed</c> covers rotations).</summary>
    private const string NotAnInstruction = "RotationSpeed(10);";

    /// <summary>Runs the sample: 0 when every action was executed, 1 when not (or the bridge could not be reached), 2 for wrong arguments.</summary>
    public static async Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        Uri? url = null;
        double speedFactor = 4;
        for (int i = 0; i < args.Length; i += 2)
        {
            string? value = i + 1 < args.Length ? args[i + 1] : null;
            bool known = value is not null && args[i] switch
            {
                "--url" => Uri.TryCreate(value, UriKind.Absolute, out url) && url.Scheme == "ws",
                "--speed-factor" => double.TryParse(value, CultureInfo.InvariantCulture, out speedFactor) && speedFactor is > 0 and <= 1000,
                _ => false,
            };
            if (!known)
            {
                error.WriteLine("Usage: BridgeClient [--url ws://127.0.0.1:6999/Bridge] [--speed-factor <times faster than real time>]");
                return SampleHost.Usage;
            }
        }

        // The bridge: one started here (on a port the system chooses, with a virtual ABB controller inside), or a running one.
        await using BridgeServer? bridge = url is null
            ? new BridgeServer(new BridgeOptions { Listen = new IPEndPoint(IPAddress.Loopback, 0), SimulationSpeed = speedFactor })
            : null;
        if (bridge is not null)
        {
            await bridge.StartAsync(cancellationToken);
            url = bridge.WebSocketUri!;
            output.WriteLine($"Started a bridge with a virtual ABB robot ({speedFactor}x real time): clients connect to {url}, its page is {bridge.PageUri}");
        }

        // The client: what Grasshopper's Connect, Send and Listen do.
        using var socket = new ClientWebSocket();
        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        timeout.CancelAfter(TimeSpan.FromMinutes(1));
        try
        {
            await socket.ConnectAsync(new Uri(url! + "?name=GH&client=Grasshopper"), timeout.Token);
        }
        catch (WebSocketException ex)
        {
            return SampleHost.Fail(error, $"could not connect to the bridge at {url}: {ex.Message} (is `machina bridge` running?)");
        }
        output.WriteLine($"Connected to {url}.");

        var issued = new List<int>();      // ids the bridge gave our actions, in order
        var executed = new List<int>();
        string? refusal = null;
        int Answered()
        {
            lock (issued)
            {
                return issued.Count;
            }
        }
        bool Executed(int id)
        {
            lock (executed)
            {
                return executed.Contains(id);
            }
        }
        var receiving = Task.Run(() => ReceiveAsync(socket, output, issued, executed, e => refusal = e, timeout.Token), CancellationToken.None);
        async Task WaitAsync()
        {
            await Task.Delay(20, timeout.Token);
            if (receiving.IsCompleted)
            {
                await receiving;   // the connection failed: its exception says why
                throw new WebSocketException("the bridge closed the connection.");
            }
        }
        try
        {
            foreach (string instruction in HelloRobot)
            {
                output.WriteLine($">> {instruction}");
                await SendAsync(socket, instruction, timeout.Token);
            }
            // Every message gets an answer: the action-issued of its action, or an error. Then wait for the last one to be executed.
            while (Answered() < HelloRobot.Length && Volatile.Read(ref refusal) is null)
            {
                await WaitAsync();
            }
            if (Volatile.Read(ref refusal) is string refused)
            {
                return SampleHost.Fail(error, $"the bridge refused part of Hello Robot: {refused} (a bridge whose robot last did AxesTo no " +
                    "longer knows the tool's pose: start it again)");
            }
            int last;
            lock (issued)
            {
                last = issued[^1];
            }
            while (!Executed(last))
            {
                await WaitAsync();
            }
            Volatile.Write(ref refusal, null);

            // Something the original bridge only logged on its own screen; this one answers with an "error" event.
            output.WriteLine($">> {NotAnInstruction}");
            await SendAsync(socket, NotAnInstruction, timeout.Token);
            using (var answer = CancellationTokenSource.CreateLinkedTokenSource(timeout.Token))
            {
                answer.CancelAfter(TimeSpan.FromSeconds(5));
                while (Volatile.Read(ref refusal) is null && !answer.IsCancellationRequested)
                {
                    await Task.Delay(20, CancellationToken.None);
                }
            }
            if (refusal is null)
            {
                output.WriteLine("(no answer to the wrong instruction: an original bridge only logs it)");
            }
            // Say goodbye; the receiving side ends when the bridge answers the close.
            await socket.CloseOutputAsync(WebSocketCloseStatus.NormalClosure, "done", timeout.Token);
            await receiving;
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            return SampleHost.Fail(error, $"the bridge did not execute Hello Robot within a minute ({executed.Count} of {HelloRobot.Length} actions executed).");
        }
        catch (WebSocketException ex)
        {
            return SampleHost.Fail(error, $"the connection to the bridge failed: {ex.Message}");
        }

        output.WriteLine($"Done: {issued.Count} actions issued, {executed.Count(issued.Contains)} executed (ids {string.Join(", ", issued)}).");
        if (bridge is not null && refusal is null)
        {
            return SampleHost.Fail(error, $"the bridge should have answered \"{NotAnInstruction}\" with an error event.");
        }
        return SampleHost.Ok;
    }

    private static Task SendAsync(ClientWebSocket socket, string instruction, CancellationToken cancellationToken) =>
        socket.SendAsync(Encoding.UTF8.GetBytes(instruction), WebSocketMessageType.Text, endOfMessage: true, cancellationToken);

    /// <summary>What Grasshopper's Listen does: every message is one JSON object with an "event"; print it, and follow our actions.</summary>
    private static async Task ReceiveAsync(ClientWebSocket socket, TextWriter output, List<int> issued, List<int> executed,
        Action<string> refused, CancellationToken cancellationToken)
    {
        var buffer = new byte[64 * 1024];
        var message = new MemoryStream();
        while (socket.State == WebSocketState.Open)
        {
            WebSocketReceiveResult result = await socket.ReceiveAsync(buffer, cancellationToken);
            if (result.MessageType == WebSocketMessageType.Close)
            {
                return;
            }
            message.Write(buffer, 0, result.Count);
            if (!result.EndOfMessage)
            {
                continue;
            }
            string json = Encoding.UTF8.GetString(message.GetBuffer(), 0, (int)message.Length);
            message.SetLength(0);
            output.WriteLine($"<< {json}");
            using JsonDocument document = JsonDocument.Parse(json);
            JsonElement root = document.RootElement;
            switch (root.GetProperty("event").GetString())
            {
                case "action-issued":
                    lock (issued)
                    {
                        issued.Add(root.GetProperty("id").GetInt32());
                    }
                    break;
                case "action-executed":
                    lock (executed)
                    {
                        executed.Add(root.GetProperty("id").GetInt32());
                    }
                    break;
                case "error":
                    refused(json);
                    break;
            }
        }
    }
}
