using System.Globalization;
using System.Net.WebSockets;
using System.Text;
using System.Text.RegularExpressions;

namespace Machina.Tests.Cli;

/// <summary>
/// The native machina (one linux-x64 file compiled ahead of time, no .NET needed) does what the JIT build does: the same
/// files, output, errors and exit codes for compile, check, run --sim, sim and bridge. The JIT build runs in-process
/// (CliRunner); the native one is a child process in its own temporary folder, loopback only, port 0, every wait bounded.
/// </summary>
public sealed partial class NativeToolTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromMinutes(1);

    private const string Program = """
        SpeedTo(100);
        MoveTo(400, 300, 500);
        Move(0, 0, -50);
        Rotate(0, 0, 1, 45);
        Wait(500);
        Message("hi <there> & é");
        AxesTo(0, 0, 0, 0, 90, 0);
        """;

    [NativeTheory]
    [InlineData("abb")]
    [InlineData("ur")]
    [InlineData("kuka")]
    [InlineData("marlin")]
    [InlineData("zmorph")]
    [InlineData("human")]
    [InlineData("machina")]
    public async Task Compile_WritesTheJitBuildsFilesByteForByte(string brand)
    {
        using var jit = new CliRunner();
        using var native = new CliRunner();
        jit.Write("p.machina", Program);
        native.Write("p.machina", Program);

        CliResult expected = await jit.RunAsync("compile", "p.machina", "--brand", brand, "--out", "build");
        CliResult actual = await NativeTool.RunAsync(native.Folder, "compile", "p.machina", "--brand", brand, "--out", "build");

        Assert.Equal(0, expected.Exit);
        Assert.Equal(expected, actual);
        string[] files = [.. Directory.EnumerateFiles(jit.PathOf("build")).Select(Path.GetFileName).Order(StringComparer.Ordinal)!];
        Assert.NotEmpty(files);
        Assert.Equal(files, Directory.EnumerateFiles(native.PathOf("build")).Select(Path.GetFileName).Order(StringComparer.Ordinal));
        Assert.All(files, f => Assert.Equal(File.ReadAllBytes(jit.PathOf(Path.Combine("build", f))), File.ReadAllBytes(native.PathOf(Path.Combine("build", f)))));
    }

    [NativeFact]
    public async Task Compile_WithWarningsAndErrors_SaysWhatTheJitBuildSays()
    {
        using var jit = new CliRunner();
        using var native = new CliRunner();
        const string warned = "MoveTo(400, 300, 500);\nMoveTo(2000, 0, 500);\n";
        const string broken = "MoveTo(400, 300, 500);\nMove(1, 2;\n";
        foreach (CliRunner cli in new[] { jit, native })
        {
            cli.Write("w.machina", warned);
            cli.Write("b.machina", broken);
        }

        string[] warnArgs = ["compile", "w.machina", "--brand", "abb", "--model", "IRB 120", "--out", "build"];
        string[] brokenArgs = ["compile", "b.machina", "--brand", "ur"];
        CliResult expectedWarn = await jit.RunAsync(warnArgs);
        CliResult expectedBroken = await jit.RunAsync(brokenArgs);

        Assert.Contains("w.machina:2:1: warning: ", expectedWarn.Stderr, StringComparison.Ordinal);
        Assert.Equal(1, expectedBroken.Exit);
        Assert.StartsWith("b.machina:2:", expectedBroken.Stderr, StringComparison.Ordinal);
        Assert.Equal(expectedWarn, await NativeTool.RunAsync(native.Folder, warnArgs));
        Assert.Equal(expectedBroken, await NativeTool.RunAsync(native.Folder, brokenArgs));
        Assert.Equal(File.ReadAllBytes(jit.PathOf("build/w.mod")), File.ReadAllBytes(native.PathOf("build/w.mod")));
    }

    [NativeTheory]
    [InlineData("IRB 120", "MoveTo(400, 300, 500);\nMove(0, 0, -50);\n")]
    [InlineData("UR5e", "MoveTo(400, 300, 500);\nMoveTo(3000, 0, 0);\nAxesTo(0, -90, 90, 0, 0, 0);\n")]
    public async Task Check_ReportsWhatTheJitBuildReports(string model, string program)
    {
        using var jit = new CliRunner();
        using var native = new CliRunner();
        jit.Write("p.machina", program);
        native.Write("p.machina", program);

        CliResult expected = await jit.RunAsync("check", "p.machina", "--model", model);
        CliResult actual = await NativeTool.RunAsync(native.Folder, "check", "p.machina", "--model", model);

        Assert.Contains(" motions checked: ", expected.Stdout, StringComparison.Ordinal);
        Assert.Equal(expected, actual);
    }

    [NativeTheory]
    [InlineData("abb")]
    [InlineData("ur")]
    [InlineData("kuka")]
    public async Task RunSim_StreamsTheProgramAsTheJitBuildDoes(string brand)
    {
        using var jit = new CliRunner();
        using var native = new CliRunner();
        jit.Write("p.machina", Program);
        native.Write("p.machina", Program);
        string[] args = ["run", "p.machina", "--brand", brand, "--sim", "--speed-factor", "1000"];

        CliResult expected = await jit.RunAsync(args);
        CliResult actual = await NativeTool.RunAsync(native.Folder, args);

        Assert.Equal(0, expected.Exit);
        Assert.Equal(0, actual.Exit);
        Assert.Contains("Done: 7 actions executed. The robot is at ", expected.Stdout, StringComparison.Ordinal);
        Assert.Equal(Steady(expected.Stdout), Steady(actual.Stdout));
        Assert.Equal(Steady(expected.Stderr), Steady(actual.Stderr));
        Assert.Contains("100%  7/7 actions  ", actual.Stdout, StringComparison.Ordinal);
    }

    [NativeFact]
    public async Task Sim_ServesALibraryHostAsTheJitBuildDoes_AndStopsOnSigterm()
    {
        using var jit = new CliRunner();
        using var native = new CliRunner();
        string[] args = ["sim", "abb", "--port", "0", "--speed-factor", "1000"];

        using var stop = new CancellationTokenSource();
        var ready = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        Task<CliResult> jitRun = jit.RunAsync(args, "", stop.Token, ready: e => ready.TrySetResult(e));
        Vector jitEnd = await DriveAsync(PortOf(await ready.Task.WaitAsync(Limit)));
        await stop.CancelAsync();
        CliResult expected = await jitRun;

        using NativeProcess process = NativeTool.Start(native.Folder, args);
        string first = await process.FirstLineAsync(Limit);
        Vector nativeEnd = await DriveAsync(int.Parse(PortPattern().Match(first).Groups[1].Value, CultureInfo.InvariantCulture));
        NativeTool.Terminate(process.Process);
        CliResult actual = await process.WaitAsync(Limit);

        Assert.Equal(new Vector(350, 50, 480), jitEnd);
        Assert.Equal(jitEnd, nativeEnd);
        Assert.Equal(0, actual.Exit);
        Assert.StartsWith("Virtual ABB controller listening on 127.0.0.1:", first, StringComparison.Ordinal);
        Assert.Contains("Stopping: 3 requests received, 3 executed, 0 malformed.", actual.Stdout, StringComparison.Ordinal);
        Assert.Contains("Stopping: 3 requests received, 3 executed, 0 malformed.", expected.Stdout, StringComparison.Ordinal);
        // The controller's activity lines interleave as the two sockets deliver them: the same lines, in any order.
        Assert.Equal(Sorted(expected.Stdout), Sorted(actual.Stdout));
        Assert.Equal(Steady(expected.Stderr), Steady(actual.Stderr));
    }

    [NativeFact]
    public async Task Bridge_ServesThePageAndEventsAsTheJitBuildDoes_AndStopsOnSigterm()
    {
        using var jit = new CliRunner();
        using var native = new CliRunner();
        string[] args = ["bridge", "--listen", "127.0.0.1:0", "--sim", "--speed-factor", "1000"];

        using var stop = new CancellationTokenSource();
        var ready = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        Task<CliResult> jitRun = jit.RunAsync(args, "", stop.Token, ready: e => ready.TrySetResult(e));
        (byte[] jitPage, string jitEvent) = await VisitAsync(new Uri(await ready.Task.WaitAsync(Limit)));
        await stop.CancelAsync();
        CliResult expected = await jitRun;

        using NativeProcess process = NativeTool.Start(native.Folder, args);
        string first = await process.FirstLineAsync(Limit);
        (byte[] nativePage, string nativeEvent) = await VisitAsync(new Uri(SocketPattern().Match(first).Value));
        NativeTool.Terminate(process.Process);
        CliResult actual = await process.WaitAsync(Limit);

        Assert.StartsWith("{\"event\":\"action-issued\"", jitEvent, StringComparison.Ordinal);
        Assert.Equal(jitEvent, nativeEvent);
        Assert.Equal(jitPage, nativePage);
        Assert.Contains("<html", Encoding.UTF8.GetString(nativePage), StringComparison.OrdinalIgnoreCase);
        Assert.Equal(0, actual.Exit);
        Assert.Equal(Steady(expected.Stdout), Steady(actual.Stdout));
        Assert.EndsWith("Bridge stopped.\n", actual.Stdout, StringComparison.Ordinal);
    }

    /// <summary>Connects the library as a host on <paramref name="port"/>, makes three moves and returns where the robot ended.</summary>
    private static async Task<Vector> DriveAsync(int port)
    {
        var robot = Robot.Create("Host", "ABB");
        robot.ControlMode("online");
        await robot.ConnectAsync("127.0.0.1", port).WaitAsync(Limit);
        robot.SpeedTo(200);
        robot.MoveTo(350, 50, 500);
        robot.Move(0, 0, -20);
        await robot.WaitForCompletionAsync().WaitAsync(Limit);
        Vector end = robot.GetExecutedState().Position!.Value;
        await robot.DisconnectAsync().WaitAsync(Limit);
        return end;
    }

    /// <summary>Gets the bridge's page and the first event after one instruction sent over its WebSocket.</summary>
    private static async Task<(byte[] Page, string Event)> VisitAsync(Uri socket)
    {
        using var http = new HttpClient { Timeout = Limit };
        byte[] page = await http.GetByteArrayAsync(new Uri($"http://{socket.Authority}/"));
        using var client = new ClientWebSocket();
        using var limit = new CancellationTokenSource(Limit);
        await client.ConnectAsync(socket, limit.Token);
        await client.SendAsync("MoveTo(400, 0, 500);"u8.ToArray(), WebSocketMessageType.Text, true, limit.Token);
        var buffer = new byte[4096];
        WebSocketReceiveResult first = await client.ReceiveAsync(buffer, limit.Token);
        return (page, Encoding.UTF8.GetString(buffer, 0, first.Count));
    }

    private static int PortOf(string endpoint) => int.Parse(endpoint.Split(':')[1], CultureInfo.InvariantCulture);

    /// <summary>Text without what changes from run to run: port numbers, rates and times left; progress lines dropped but the last.</summary>
    private static string Steady(string text)
    {
        string[] lines = text.Split('\n');
        string lastProgress = lines.LastOrDefault(l => ProgressPattern().IsMatch(l)) ?? "";
        string kept = string.Join('\n', lines.Where(l => !ProgressPattern().IsMatch(l) || ReferenceEquals(l, lastProgress)));
        string steady = TimeLeftPattern().Replace(RatePattern().Replace(EndpointPattern().Replace(kept, "${1}PORT"), "RATE/s"), "T left");
        // Each ABB twin's HOME: is a new temporary folder: its name differs from run to run.
        return TemporaryHomePattern().Replace(steady, "machina-rapid-home-NAME");
    }

    /// <summary>
    /// The lines in order, without those whose grouping or presence depends on timing: the RAPID driver's pendant lines after
    /// the host left ("client disconnected", "waiting for a client": printed or not before the tool is stopped), the relay's
    /// "disconnected (driver|monitor)" lines (the same: each is printed when its socket's close is seen) and the
    /// "executed #…" lines (acknowledgements are grouped as they arrive). The counts and the end pose are compared apart.
    /// </summary>
    private static string[] Sorted(string text) =>
        [.. Steady(text).Split('\n').Where(l => !TimingDependentLinePattern().IsMatch(l)).Order(StringComparer.Ordinal)];

    [GeneratedRegex(@"machina-rapid-home-\w+")]
    private static partial Regex TemporaryHomePattern();

    [GeneratedRegex(@"^\s*(pendant: Machina (client disconnected|driver waiting for a client)|executed  #|\S+ disconnected \((driver|monitor)\))")]
    private static partial Regex TimingDependentLinePattern();

    [GeneratedRegex(@"^\s*\d+%\s")]
    private static partial Regex ProgressPattern();

    [GeneratedRegex(@"(127\.0\.0\.1:|port |on |--port )\d{2,5}(?!\d|\.\d)")]
    private static partial Regex EndpointPattern();

    [GeneratedRegex(@"\d+(\.\d+)?/s")]
    private static partial Regex RatePattern();

    [GeneratedRegex(@"\d+:\d\d left")]
    private static partial Regex TimeLeftPattern();

    [GeneratedRegex(@"listening on 127\.0\.0\.1:(\d+)")]
    private static partial Regex PortPattern();

    [GeneratedRegex(@"ws://127\.0\.0\.1:\d+/Bridge")]
    private static partial Regex SocketPattern();
}
