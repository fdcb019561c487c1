using System.Globalization;
using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

/// <summary>
/// The keys of <c>machina run</c> (space: pause / resume, s: stop), typed on redirected standard input while a slow move (10 mm/s)
/// runs on the ABB twin that runs the RAPID driver (and a stop on the KRL twin that runs drivers/kuka): the key is typed once the
/// arm has left its start, so it acts mid-move.
/// </summary>
public class RunKeysTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    /// <summary>Standard input a test types into: Read blocks until a key is pressed or the input ends.</summary>
    private sealed class Keyboard : TextReader
    {
        private readonly BlockingCollection<int> _keys = [];

        public void Press(char key) => _keys.Add(key);

        public void End() => _keys.Add(-1);

        public override int Read() => _keys.Take();

        public override int Peek() => -1;
    }

    private static async Task<VirtualAbbController> StartAsync()
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions());
        await controller.StartAsync().WaitAsync(Long);
        return controller;
    }

    [Fact]
    public async Task Run_SKey_StopsTheMoveWhereTheArmIs_TheRunEndsAtItsLine_NothingAfterRuns()
    {
        await using VirtualAbbController controller = await StartAsync();
        using var cli = new CliRunner();
        cli.Write("p.machina", "SpeedTo(10);\nMove(0, 0, -200);\nWriteDigital(\"DO_2\", true);\n");
        var keys = new Keyboard();
        var stdout = new WatchedWriter();
        Vector start = controller.State.Position;
        try
        {
            Task<CliResult> run = cli.RunAsync(["run", "p.machina", "--brand", "abb", "--host", "127.0.0.1", "--port", controller.Port.ToString(CultureInfo.InvariantCulture)], keys, stdout);
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);
            keys.Press('s');
            CliResult result = await run;

            Vector at = controller.State.Position;
            Assert.True(result.Exit == 1, result.Stderr + result.Stdout);
            Assert.Contains("Keys (then Enter): space pauses or resumes the robot, s stops it.", result.Stdout, StringComparison.Ordinal);
            Assert.Contains("Stopping the robot (s)...", result.Stdout, StringComparison.Ordinal);
            Assert.Matches(@"p\.machina:2:1: error: stopped by the user \(s\): .+ stopped where the arm was and nothing after it ran\.", result.Stderr);
            Assert.True(Vector.Distance(at, start + new Vector(0, 0, -200)) > 50, $"the arm reached {at}");
            await Task.Delay(300);
            Assert.True(Vector.Distance(controller.State.Position, at) < 0.01, controller.State.Position.ToString());
            Assert.DoesNotContain("DO_2", controller.State.DigitalOutputs.Keys);
        }
        finally
        {
            keys.End();
        }
    }

    [Fact]
    public async Task Run_SpaceKey_PausesTheMove_SpaceAgainResumes_TheProgramFinishesOnce()
    {
        await using VirtualAbbController controller = await StartAsync();
        using var cli = new CliRunner();
        cli.Write("p.machina", "SpeedTo(10);\nMove(0, 0, -60);\nWriteDigital(\"DO_2\", true);\n");
        var keys = new Keyboard();
        var stdout = new WatchedWriter();
        Vector start = controller.State.Position;
        try
        {
            Task<CliResult> run = cli.RunAsync(["run", "p.machina", "--brand", "abb", "--host", "127.0.0.1", "--port", controller.Port.ToString(CultureInfo.InvariantCulture)], keys, stdout);
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);
            keys.Press(' ');
            await stdout.WaitForAsync("Paused: the arm holds where it is. Press space to resume, s to stop.");
            Vector held = controller.State.Position;
            await Task.Delay(300);
            Assert.True(Vector.Distance(controller.State.Position, held) < 0.01, $"the arm moved from {held} while paused");
            Assert.True(Vector.Distance(held, start + new Vector(0, 0, -60)) > 10, $"the arm reached {held}");
            keys.Press(' ');
            CliResult result = await run;

            Assert.True(result.Exit == 0, result.Stderr + result.Stdout);
            Assert.Contains("Resumed.", result.Stdout, StringComparison.Ordinal);
            Assert.Contains("Done: 3 actions executed.", result.Stdout, StringComparison.Ordinal);
            Assert.True(controller.State.Position.IsSimilar(start + new Vector(0, 0, -60), 1e-2), controller.State.Position.ToString());
            Assert.True(controller.State.DigitalOutputs["DO_2"]);
        }
        finally
        {
            keys.End();
        }
    }

    [Fact]
    public async Task Run_SKey_OnKuka_StopsTheMoveWhereTheArmIs_TheRunEndsAtItsLine_NothingAfterRuns()
    {
        await using var controller = new VirtualKukaController(new VirtualKukaControllerOptions());
        await controller.StartAsync().WaitAsync(Long);
        using var cli = new CliRunner();
        cli.Write("p.machina", "SpeedTo(10);\nMove(0, 0, -200);\nWriteDigital(2, true);\n");
        var keys = new Keyboard();
        var stdout = new WatchedWriter();
        Vector start = controller.State.Position;
        try
        {
            Task<CliResult> run = cli.RunAsync(["run", "p.machina", "--brand", "kuka", "--host", "127.0.0.1", "--port", controller.Port.ToString(CultureInfo.InvariantCulture)], keys, stdout);
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);
            keys.Press('s');
            CliResult result = await run.WaitAsync(Long);

            Vector at = controller.State.Position;
            Assert.True(result.Exit == 1, result.Stderr + result.Stdout);
            Assert.Contains("Stopping the robot (s)...", result.Stdout, StringComparison.Ordinal);
            Assert.Matches(@"p\.machina:2:1: error: stopped by the user \(s\): .+ stopped where the arm was and nothing after it ran\.", result.Stderr);
            Assert.True(Vector.Distance(at, start + new Vector(0, 0, -200)) > 50, $"the arm reached {at}");
            await Task.Delay(300);
            Assert.True(Vector.Distance(controller.State.Position, at) < 0.01, controller.State.Position.ToString());
            Assert.DoesNotContain("2", controller.State.DigitalOutputs.Keys);
        }
        finally
        {
            keys.End();
        }
    }
}
