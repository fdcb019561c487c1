using System.Net;
using System.Net.Sockets;
using Machina.Cli.Simulation;

namespace Machina.Tests.Cli;

public class OnlineCommandTests
{
    private const string Program = """
        SpeedTo(200);
        MoveTo(300, -100, 400);
        Move(0, 0, -100);
        Move(150, 0, 0);
        Move(0, 200, 0);
        Wait(10);
        AxesTo(0, 0, 0, 0, 90, 0);
        """;

    public static TheoryData<string> SimulatedBrands => new(VirtualControllers.Available.Select(b => b.ToString().ToLowerInvariant()));

    [Theory]
    [MemberData(nameof(SimulatedBrands))]
    public async Task Run_Sim_CompletesTheProgram(string brand)
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("run", Program, "--brand", brand, "--sim", "--speed-factor", "1000");

        Assert.Equal(0, result.Exit);
        Assert.Matches(@"p\.machina checked: 7 actions, every target within the .+'s reach and limits\. Streaming it\.\.\.", result.Stdout);
        Assert.Matches(@"(?m)^100%  7/7 actions  [\d.]+/s  line 7$", result.Stdout);
        Assert.Matches(@"(?m)^ 14%  1/7 actions  [\d.]+/s  [\d:]+ left  line 1$", result.Stdout);
        Assert.Contains("Done: 7 actions executed.", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("axes [0, 0, 0, 0, 90, 0]", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Run_StandardInput_StreamsWithoutATotal()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync(["run", "-", "--brand", "abb", "--sim", "--speed-factor", "1000"], Program, CancellationToken.None);

        Assert.Equal(0, result.Exit);
        Assert.Contains("Done: 7 actions executed.", result.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("%", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Run_MalformedLine_StopsBeforeConnecting()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("run", Program + "\nMoveTo(1, 2);\n", "--brand", "abb", "--sim");

        Assert.Equal(1, result.Exit);
        Assert.StartsWith("p.machina:8:1: error: MoveTo was given 2 arguments", result.Stderr, StringComparison.Ordinal);
        Assert.DoesNotContain("Connecting", result.Stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--brand", "zmorph", "--sim", "only robot arms")]
    [InlineData("--brand", "abb", "--port", "needs either --sim")]
    public async Task Run_WrongArguments_AreUsageErrors(string o1, string v1, string o2, string message)
    {
        using var cli = new CliRunner();
        cli.Write("p.machina", Program);
        string[] args = o2 == "--port" ? ["run", "p.machina", o1, v1, o2, "7000"] : ["run", "p.machina", o1, v1, o2];

        CliResult result = await cli.RunAsync(args);

        Assert.Equal(2, result.Exit);
        Assert.Contains(message, result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Run_CtrlC_StopsCleanlyAndSaysWhatWasSent()
    {
        using var cli = new CliRunner();
        // 50 actions: the first 6 run at once (progress reaches 10%), then a wait of 10 minutes holds the rest.
        cli.Write("p.machina", "MoveTo(300, 0, 400);\n" + string.Concat(Enumerable.Repeat("Move(0, 0, 1);\n", 5)) + "Wait(600000000);\n" +
            string.Concat(Enumerable.Repeat("Move(0, 0, 1);\n", 43)));
        using var cancel = new CancellationTokenSource();
        var stdout = new WatchedWriter();

        Task<CliResult> run = cli.RunAsync(["run", "p.machina", "--brand", "abb", "--sim", "--speed-factor", "1000"], "", cancel.Token, stdout);
        await stdout.WaitForAsync(" 10%  5/50 actions");
        await cancel.CancelAsync();
        CliResult result = await run;

        Assert.Equal(130, result.Exit);
        Assert.Matches(@"^Stopped \(Ctrl\+C\) after [56] of 50 actions were executed \(\d+ issued\); \d+ not sent yet were cancelled\. [1-9]\d* were sent", result.Stderr);
        Assert.Contains("the controller may still run them", result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Sim_AcceptsTheLibrarysOwnHost_AndLogsWhatItReceives()
    {
        using var cli = new CliRunner();
        using var cancel = new CancellationTokenSource();
        var endpoint = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var stdout = new WatchedWriter();
        Task<CliResult> sim = cli.RunAsync(["sim", "abb", "--port", "0", "--speed-factor", "1000"], "", cancel.Token, stdout, ready: e => endpoint.TrySetResult(e));
        int port = int.Parse(((await endpoint.Task.WaitAsync(TimeSpan.FromSeconds(60))).Split(':')[1]), System.Globalization.CultureInfo.InvariantCulture);

        var robot = Robot.Create("Host", "ABB");
        robot.ControlMode("online");
        await robot.ConnectAsync("127.0.0.1", port);
        robot.SpeedTo(200);
        robot.MoveTo(350, 50, 500);
        robot.Move(0, 0, -20);
        await robot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromSeconds(60));
        RobotState state = robot.GetExecutedState();
        await robot.DisconnectAsync();
        await cancel.CancelAsync();
        CliResult result = await sim;

        Assert.Equal(0, result.Exit);
        Assert.Equal(new Vector(350, 50, 480), state.Position);
        Assert.Contains($"Virtual ABB controller listening on 127.0.0.1:{port} (driver port; monitor on {port + 1})", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("connected (driver)", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  received  MoveL           @2 1 350 50 500 ", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  received  MoveL           @3 1 350 50 480 ", result.Stdout, StringComparison.Ordinal);
        Assert.Contains($"the tool is now at {state.Position} mm", result.Stdout.Split('\n').Last(l => l.StartsWith("  executed  ", StringComparison.Ordinal)), StringComparison.Ordinal);
        Assert.Contains("Stopping: 3 requests received, 3 executed, 0 malformed.", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Run_NoControllerListening_SaysTheLinkFailed()
    {
        using var cli = new CliRunner();
        cli.Write("p.machina", Program);
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int closed = ((IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();

        CliResult result = await cli.RunAsync("run", "p.machina", "--brand", "abb", "--host", "127.0.0.1", "--port", closed.ToString(System.Globalization.CultureInfo.InvariantCulture));

        Assert.Equal(1, result.Exit);
        Assert.StartsWith("machina: error: the robot link failed: ", result.Stderr, StringComparison.Ordinal);
        Assert.DoesNotContain("Connected.", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Sim_PortInUse_SaysSo()
    {
        using var cli = new CliRunner();
        var taken = new TcpListener(IPAddress.Loopback, 0);
        taken.Start();
        try
        {
            int port = ((IPEndPoint)taken.LocalEndpoint).Port;

            CliResult result = await cli.RunAsync("sim", "abb", "--port", port.ToString(System.Globalization.CultureInfo.InvariantCulture));

            Assert.Equal(1, result.Exit);
            Assert.Contains("is already in use", result.Stderr, StringComparison.Ordinal);
        }
        finally
        {
            taken.Stop();
        }
    }
}
