using Machina.Cli;
using Machina.Cli.Programs;
using Machina.Cli.Terminal;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

public class CommandLineTests
{
    public static TheoryData<string> Commands => new(CliApp.Commands.Select(c => c.Name));

    [Fact]
    public async Task Help_ListsEveryCommand()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("--help");
        CliResult none = await cli.RunAsync();

        Assert.Equal(0, result.Exit);
        Assert.Equal(2, none.Exit);
        Assert.All(CliApp.Commands, c => Assert.Contains($"  {c.Name,-9} {c.Summary}", result.Stdout, StringComparison.Ordinal));
        Assert.Equal(result.Stdout, none.Stdout);
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public async Task CommandHelp_StartsWithItsUsageAndNamesEveryOption(string command)
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync(command, "--help");
        CliResult viaHelp = await cli.RunAsync("help", command);

        Assert.Equal(0, result.Exit);
        Assert.StartsWith($"Usage: machina {command}", result.Stdout, StringComparison.Ordinal);
        CliCommand spec = CliApp.Commands.Single(c => c.Name == command);
        Assert.All(spec.Options.Concat(spec.Flags), o => Assert.Contains(o, result.Stdout, StringComparison.Ordinal));
        Assert.Equal(result.Stdout, viaHelp.Stdout);
    }

    [Fact]
    public async Task Version_NamesTheLibraryVersion()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("--version");

        Assert.Equal(0, result.Exit);
        Assert.StartsWith($"machina {Robot.Version} ", result.Stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(new[] { "compil" }, "\"compil\" is not a machina command. Did you mean \"compile\"?")]
    [InlineData(new[] { "compile", "p.machina", "--brnd", "abb" }, "\"--brnd\" is not an option of machina compile. Did you mean --brand?")]
    [InlineData(new[] { "compile", "p.machina" }, "machina compile needs --brand")]
    [InlineData(new[] { "compile", "--brand", "abb" }, "machina compile needs a PROGRAM file")]
    [InlineData(new[] { "compile", "a", "b", "--brand", "abb" }, "takes one a PROGRAM file (or - for standard input), but was given 2: a b")]
    [InlineData(new[] { "compile", "p.machina", "--brand" }, "--brand needs a value, e.g. --brand abb")]
    [InlineData(new[] { "compile", "p.machina", "--brand", "abb", "--brand", "ur" }, "--brand is given twice")]
    [InlineData(new[] { "sim", "abb", "--port", "70000" }, "--port must be a port number from 0 to 65535, not \"70000\"")]
    [InlineData(new[] { "sim", "abb", "--speed-factor", "-1" }, "--speed-factor must be a number greater than 0")]
    [InlineData(new[] { "sim", "abb", "--bind", "localhost:1" }, "--bind needs an IP address")]
    [InlineData(new[] { "sim", "abb", "--load", "p.machina", "--bind", "localhost:1" }, "--bind needs an IP address")]
    [InlineData(new[] { "sim", "kuka", "--load", "p.machina", "--speed-factor", "0" }, "--speed-factor must be a number greater than 0")]
    [InlineData(new[] { "sim", "marlin" }, "\"marlin\" is not a brand sim accepts here; use one of: abb, ur, kuka.")]
    [InlineData(new[] { "drivers", "abb", "--host", "1.2.3.4", "--out", "d" }, "machina drivers needs --port P")]
    [InlineData(new[] { "models", "IRB", "120" }, "quote names with spaces")]
    [InlineData(new[] { "models", "IRB 9999" }, "There is no robot model called \"IRB 9999\"")]
    [InlineData(new[] { "check", "p.machina" }, "machina check needs --model")]
    public async Task BadArguments_AreUsageErrorsThatSayWhatToDo(string[] args, string message)
    {
        using var cli = new CliRunner();
        cli.Write("p.machina", "MoveTo(300, 0, 400);");

        CliResult result = await cli.RunAsync(args);

        Assert.Equal(2, result.Exit);
        Assert.StartsWith("machina: error: ", result.Stderr, StringComparison.Ordinal);
        Assert.Contains(message, result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task OptionWithEquals_IsAccepted()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("compile", "MoveTo(300, 0, 400);", "--brand=human", "--out=o");

        Assert.Equal(0, result.Exit);
        Assert.True(File.Exists(cli.PathOf("o/p.txt")));
    }

    [Fact]
    public async Task Check_ReportsEveryMotionByLine_AndFailsOnProblems()
    {
        using var cli = new CliRunner();
        cli.Write("good.machina", "SpeedTo(50);\nMoveTo(300, 0, 400);\nMove(0, 0, -50); Move(50, 0, 0);\n");
        cli.Write("bad.machina", "MoveTo(300, 0, 400);\nMoveTo(900, 0, 400);\nMove(0, 0, 1);\n");

        CliResult good = await cli.RunAsync("check", "good.machina", "--model", "IRB 120");
        CliResult bad = await cli.RunAsync("check", "bad.machina", "--model", "irb120", "--problems-only");

        Assert.Equal(0, good.Exit);
        Assert.Contains("      2:1   ok       MoveTo(300,0,400);", good.Stdout, StringComparison.Ordinal);
        Assert.Contains("      3:18  ok       Move(50,0,0);", good.Stdout, StringComparison.Ordinal);
        Assert.Contains("3 motions checked: 3 ok, 0 with problems, 0 refused (of 4 actions).", good.Stdout, StringComparison.Ordinal);
        // Two 50 mm moves at 50 mm/s, ramping at the ABB's assumed 5 m/s²: 1 s + 0.01 s each exact (2.02 s), but the corner between
        // them is rounded in Machina's default 5 mm zone (the arm crosses an 8.1 mm parabola at 50 mm/s instead of stopping): 1.97 s.
        Assert.Contains("Estimated cycle time on the ABB IRB 120: 1.97 s (motion 1.97 s, waits 0.00 s); 1 motion not timed: " +
            "where it starts is not known (before the first absolute position, or joints without a --model).", good.Stdout, StringComparison.Ordinal);
        Assert.Equal(1, bad.Exit);
        Assert.Contains("      2:1   PROBLEM  MoveTo(900,0,400);\n                     Unreachable: the target [900, 0, 400] is out of reach of the ABB IRB 120.", bad.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain(" ok ", bad.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Models_ListsTheCatalogue_AndShowsOne()
    {
        using var cli = new CliRunner();

        CliResult all = await cli.RunAsync("models");
        CliResult ur = await cli.RunAsync("models", "--brand", "ur");
        CliResult one = await cli.RunAsync("models", "ur5e");

        Assert.Equal(0, all.Exit);
        Assert.All(RobotModels.All, m => Assert.Contains(m.Name + " ", all.Stdout, StringComparison.Ordinal));
        Assert.Contains($"{RobotModels.All.Count} models.", all.Stdout, StringComparison.Ordinal);
        Assert.Equal(RobotModels.All.Count(m => m.Brand == "UR"), ur.Lines.Length - 2);
        Assert.StartsWith("UR5e (UR, UniversalRobots kinematics)", one.Stdout, StringComparison.Ordinal);
        Assert.Contains(RobotModels.Get("UR5e").Source, one.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Drivers_WritesTheLibrarysFilledInModules()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("drivers", "abb", "--host", "192.168.125.1", "--port", "7000", "--out", "driver");
        CliResult ur = await cli.RunAsync("drivers", "ur", "--host", "192.168.0.9", "--port", "30002", "--out", "driver-ur");

        Assert.Equal(0, result.Exit);
        IReadOnlyDictionary<string, string> expected = Robot.Create("X", "ABB").GetDeviceDriverModules(
            new Dictionary<string, string> { ["HOSTNAME"] = "192.168.125.1", ["PORT"] = "7000" });
        Assert.Equal(expected.Keys.Order().Select(k => Path.Combine("driver", k)), result.Lines);
        Assert.All(expected, f => Assert.Equal(f.Value, File.ReadAllText(cli.PathOf(Path.Combine("driver", f.Key)))));
        Assert.Contains("192.168.125.1", File.ReadAllText(cli.PathOf("driver/machina_abb_driver.mod")), StringComparison.Ordinal);
        Assert.Equal(0, ur.Exit);
        IReadOnlyDictionary<string, string> expectedUr = Robot.Create("X", "UR").GetDeviceDriverModules(
            new Dictionary<string, string> { ["HOSTNAME"] = "192.168.0.9", ["PORT"] = "30002" });
        Assert.All(expectedUr, f => Assert.Equal(f.Value, File.ReadAllText(cli.PathOf(Path.Combine("driver-ur", f.Key)))));
    }

    [Fact]
    public async Task Bridge_Sim_ServesUntilCancelledAndAClientGetsEvents()
    {
        using var cli = new CliRunner();
        using var stop = new CancellationTokenSource();
        var ready = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);

        Task<CliResult> running = cli.RunAsync(["bridge", "--listen", "127.0.0.1:0", "--sim", "--speed-factor", "1000"], "", stop.Token, ready: ready.SetResult);
        string url = await ready.Task.WaitAsync(TimeSpan.FromMinutes(1));
        using (var client = new System.Net.WebSockets.ClientWebSocket())
        {
            await client.ConnectAsync(new Uri(url), CancellationToken.None).WaitAsync(TimeSpan.FromMinutes(1));
            await client.SendAsync("MoveTo(400, 0, 500);"u8.ToArray(), System.Net.WebSockets.WebSocketMessageType.Text, true, CancellationToken.None);
            var buffer = new byte[4096];
            System.Net.WebSockets.WebSocketReceiveResult first = await client.ReceiveAsync(buffer, CancellationToken.None).WaitAsync(TimeSpan.FromMinutes(1));
            Assert.StartsWith("{\"event\":\"action-issued\"", System.Text.Encoding.UTF8.GetString(buffer, 0, first.Count), StringComparison.Ordinal);
        }
        stop.Cancel();
        CliResult result = await running;

        Assert.Equal(0, result.Exit);
        Assert.StartsWith("ws://127.0.0.1:", url, StringComparison.Ordinal);
        Assert.Contains($"Machina Bridge for a virtual ABB robot: apps connect to {url}", result.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("Bridge stopped.\n", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void ProgramReader_GivesEachStatementTheLibrarysPosition_OutsideParenthesesStringsAndComments()
    {
        string text = "MoveTo(1, 2, 3); Wait(5) // Note(1)\n  Message(\"a ) Fake(2)\"); Move(0,\n 0, // x) Bad(\n 1);";

        List<(string, int, int)> statements = [.. InstructionStatement.ReadAll(new StringReader(text), CancellationToken.None)
            .Select(s => (s.Action.ToInstruction(), s.Line, s.Column))];

        Assert.Equal([("MoveTo(1,2,3);", 1, 1), ("Wait(5);", 1, 18), ("Message(\"a ) Fake(2)\");", 2, 3), ("Move(0,0,1);", 2, 27)], statements);
    }

    [Fact]
    public void Progress_Redirected_PrintsAPlainLineAtEveryTenth()
    {
        var clock = new ManualClock();
        var output = new StringWriter();
        var progress = new ProgressReporter(new CliContext(TextReader.Null, output, TextWriter.Null, CancellationToken.None, isTerminal: false, clock), 20);

        for (int i = 1; i <= 20; i++)
        {
            clock.Advance(TimeSpan.FromSeconds(1));
            progress.Update(i, i + 1);
        }

        string[] lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(10, lines.Length);
        Assert.Equal(" 10%  2/20 actions  1.0/s  0:18 left  line 3", lines[0]);
        Assert.Equal("100%  20/20 actions  1.0/s  line 21", lines[^1]);
    }

    [Fact]
    public void Progress_OnATerminal_RedrawsOneLineWithABar()
    {
        var clock = new ManualClock();
        var output = new StringWriter();
        var progress = new ProgressReporter(new CliContext(TextReader.Null, output, TextWriter.Null, CancellationToken.None, isTerminal: true, clock), 4);

        clock.Advance(TimeSpan.FromSeconds(2));
        progress.Update(1, 7);
        progress.Update(2, 8); // within 100 ms of the last drawing: skipped
        clock.Advance(TimeSpan.FromSeconds(2));
        progress.Update(4, 9);
        progress.Finish();

        const string First = "[######------------------]  25%  1/4 actions  0.5/s  0:06 left  line 7";
        const string Last = "[########################] 100%  4/4 actions  1.0/s  line 9";
        Assert.Equal("\r" + First + "\r" + Last.PadRight(First.Length) + "\n", output.ToString().Replace(Environment.NewLine, "\n", StringComparison.Ordinal));
    }
}
