namespace Machina.Tests.Cli;

/// <summary>
/// <c>machina sim</c> tells what the controller does (the driver program starting, each request it accepts, where the robot is
/// after what it finished, outputs) and names every port for what it is, instead of numbering the lines of a driver script.
/// </summary>
public sealed class SimActivityTests
{
    [Fact]
    public async Task SimUr_TellsTheProgramTheRequestsAndThePose_NotTheScriptLines()
    {
        using var cli = new CliRunner();
        using var cancel = new CancellationTokenSource();
        var endpoint = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var stdout = new WatchedWriter();
        Task<CliResult> sim = cli.RunAsync(["sim", "ur", "--port", "0", "--speed-factor", "1000"], "", cancel.Token, stdout, ready: e => endpoint.TrySetResult(e));
        int port = int.Parse((await endpoint.Task.WaitAsync(TimeSpan.FromSeconds(60))).Split(':')[1], System.Globalization.CultureInfo.InvariantCulture);

        RobotState state;
        await using (var robot = Robot.Create("Host", "UR"))
        {
            robot.ControlMode("online");
            await robot.ConnectAsync("127.0.0.1", port).WaitAsync(TimeSpan.FromSeconds(60));
            robot.SpeedTo(200);
            robot.TransformTo(300, 100, 400, -1, 0, 0, 0, 1, 0);
            robot.Move(0, 0, -50);
            robot.WriteDigital(1, true);
            await robot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromSeconds(60));
            state = robot.GetExecutedState();
            await robot.DisconnectAsync();
        }
        await cancel.CancelAsync();
        CliResult result = await sim;

        Assert.Equal(0, result.Exit);
        string[] lines = result.Stdout.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
        Assert.Contains($"Virtual UR controller listening on 127.0.0.1:{port} (script port; RTDE on {port + 1}, dashboard on {port + 2})", lines[0], StringComparison.Ordinal);
        Assert.DoesNotContain("monitor on", result.Stdout, StringComparison.Ordinal);
        // The driver's own textmsg, as the URScript twin runs it (a real UR shows it in its log).
        Assert.Contains(lines, l => l.StartsWith("  pendant: Machina driver 3.0.0 connected to ", StringComparison.Ordinal));
        Assert.DoesNotContain(lines, l => l.Contains("def machina_ur_driver", StringComparison.Ordinal) || l.Contains("#1 received", StringComparison.Ordinal));
        string stopping = lines.Single(l => l.StartsWith("Stopping: ", StringComparison.Ordinal));
        int received = int.Parse(stopping["Stopping: ".Length..].Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
        Assert.Equal(received, lines.Count(l => l.StartsWith("  received  ", StringComparison.Ordinal)));
        Assert.InRange(received, 3, 10);
        Assert.Equal(new Vector(300, 100, 350), state.Position);
        string lastExecuted = lines.Last(l => l.StartsWith("  executed  ", StringComparison.Ordinal));
        Assert.Contains($"the tool is now at {state.Position} mm", lastExecuted, StringComparison.Ordinal);
        Assert.Contains("  output    digital 1 on", lines);
        Assert.Contains(lines, l => l.StartsWith("  received  MoveL           ", StringComparison.Ordinal) && l.EndsWith(" 1 300000 100000 350000 0 3141593 0", StringComparison.Ordinal));
        Assert.Contains(lines, l => l.StartsWith("  received  SetDigitalOut   ", StringComparison.Ordinal));
        Assert.True(Array.IndexOf(lines, "  output    digital 1 on") < Array.IndexOf(lines, stopping));
    }

    [Fact]
    public async Task SimKuka_NamesTheDriverAndMonitorPorts_AndCountsOneLinePerRequest()
    {
        using var cli = new CliRunner();
        using var cancel = new CancellationTokenSource();
        var endpoint = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var stdout = new WatchedWriter();
        Task<CliResult> sim = cli.RunAsync(["sim", "kuka", "--port", "0", "--speed-factor", "1000"], "", cancel.Token, stdout, ready: e => endpoint.TrySetResult(e));
        int port = int.Parse((await endpoint.Task.WaitAsync(TimeSpan.FromSeconds(60))).Split(':')[1], System.Globalization.CultureInfo.InvariantCulture);

        await using (var robot = Robot.Create("Host", "KUKA"))
        {
            robot.ControlMode("online");
            await robot.ConnectAsync("127.0.0.1", port).WaitAsync(TimeSpan.FromSeconds(60));
            robot.SpeedTo(200);
            robot.TransformTo(500, 0, 600, -1, 0, 0, 0, 1, 0);
            robot.Move(0, 0, -50);
            await robot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromSeconds(60));
            await robot.DisconnectAsync();
        }
        await cancel.CancelAsync();
        CliResult result = await sim;

        Assert.Equal(0, result.Exit);
        string[] lines = result.Stdout.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
        Assert.Contains($"Virtual KUKA controller listening on 127.0.0.1:{port} (driver port; monitor on {port + 1})", lines[0], StringComparison.Ordinal);
        string stopping = lines.Single(l => l.StartsWith("Stopping: ", StringComparison.Ordinal));
        int received = int.Parse(stopping["Stopping: ".Length..].Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
        Assert.Equal(received, lines.Count(l => l.StartsWith("  received  ", StringComparison.Ordinal)));
        Assert.DoesNotContain(lines, l => l.Contains("<?xml", StringComparison.Ordinal) || l.Contains("#1 received", StringComparison.Ordinal));
        Assert.Contains("the tool is now at [500, 0, 550] mm", lines.Last(l => l.StartsWith("  executed  ", StringComparison.Ordinal)), StringComparison.Ordinal);
    }
}
