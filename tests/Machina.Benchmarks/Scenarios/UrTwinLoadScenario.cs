using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;

namespace Machina.Benchmarks;

/// <summary>
/// Sends a compiled-style URScript program of <c>size</c> lines (movel, digital outputs, waits) to the script port of a virtual UR
/// that runs scripts, and times from the connection until the program runs (its first line shows on the pendant): reading,
/// compiling and starting it, and stopping the program the previous run started (a new program stops the running one).
/// </summary>
internal sealed class UrTwinLoadScenario : Scenario
{
    private VirtualUrController? _controller;
    private TcpClient? _client;

    public override string Name => "ur-twin-load";

    public override string Title => "Load and start a URScript program on the virtual UR's interpreter";

    public override string Unit => "line";

    public override int TargetSize => 100_000;

    public override IReadOnlyList<int> ScalingSizes => [10_000, 100_000];

    public override Target Target { get; } = Target.Seconds(1, 100_000, "<= 1 s per 10^5 lines");

    public override bool MultiThreaded => true;

    public override Func<object?> Prepare(int size)
    {
        byte[] program = Encoding.ASCII.GetBytes(Program(size));
        var controller = new VirtualUrController(new VirtualUrControllerOptions { RunsScripts = true });
        controller.StartAsync().GetAwaiter().GetResult();
        _controller = controller;
        return () =>
        {
            int before = controller.PendantMessages.Count(m => m == "started");
            _client?.Dispose();
            var client = new TcpClient();
            _client = client;
            client.Connect(IPAddress.Loopback, controller.Port);
            client.GetStream().Write(program);
            long start = Stopwatch.GetTimestamp();
            while (controller.PendantMessages.Count(m => m == "started") == before)
            {
                if (Stopwatch.GetElapsedTime(start) > TimeSpan.FromMinutes(1))
                {
                    throw new TimeoutException("The program did not start within a minute: " + string.Join(" | ", controller.Errors));
                }
                Thread.Sleep(1);
            }
            return null;
        };
    }

    /// <summary>A program shaped like the library's compiled URScript: a definition, its settings, then moves, outputs and waits.</summary>
    private static string Program(int lines)
    {
        var text = new StringBuilder(lines * 64);
        text.Append("def big():\n  textmsg(\"started\")\n  set_tcp(p[0, 0, 0.1, 0, 0, 0])\n");
        for (int i = 3; i < lines - 1; i++)
        {
            double x = 0.3 + (i % 100) * 0.001;
            text.Append((i % 10) switch
            {
                0 => $"  set_standard_digital_out({i % 8}, {(i % 20 == 0 ? "True" : "False")})\n",
                5 => "  sleep(0.001)\n",
                _ => FormattableString.Invariant($"  movel(p[{x:0.###}, -0.3, 0.4, 0, 3.1416, 0], a=1.2, v=0.25, r=0.001)\n"),
            });
        }
        return text.Append("end").ToString();
    }

    public override void Cleanup()
    {
        _client?.Dispose();
        _controller?.DisposeAsync().AsTask().GetAwaiter().GetResult();
        _client = null;
        _controller = null;
    }
}
