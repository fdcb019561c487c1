using System.Collections.Concurrent;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The unchanged drivers/kuka files (only their placeholders filled: loopback, port 0 for a free one, $ADVANCE 3) run on the
/// KRL twin with EthernetKRL, and a real online KUKA Robot streams through them.
/// </summary>
public class KrlDriverTwinTests
{
    private static string Fill(string file) => Machina.KukaDriverModules.Read(file)
        .Replace("{{HOSTNAME}}", "127.0.0.1", StringComparison.Ordinal).Replace("{{PORT}}", "0", StringComparison.Ordinal)
        .Replace("{{ADVANCE}}", "3", StringComparison.Ordinal);

    /// <summary>The driver running on a twin, its program on a thread of its own until disposed.</summary>
    private sealed class DriverTwin : IAsyncDisposable
    {
        private readonly CancellationTokenSource _stop = new();

        public DriverTwin(KrlTwinOptions? options)
        {
            Twin = new KrlTwinController(options);
            Twin.AddEkiConfiguration("machina_kuka_server", Fill("machina_kuka_server.xml"));
            Twin.Load(("machina_kuka_driver.src", Fill("machina_kuka_driver.src")), ("machina_kuka_driver.dat", Fill("machina_kuka_driver.dat")),
                ("machina_kuka_monitor.src", Fill("machina_kuka_monitor.src")), ("machina_kuka_monitor.dat", Fill("machina_kuka_monitor.dat")));
            Program = Task.Factory.StartNew(() => Twin.Run("machina_kuka_driver", _stop.Token), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        }

        public KrlTwinController Twin { get; }

        public Task<KrlProgramState> Program { get; }

        public async ValueTask DisposeAsync()
        {
            await _stop.CancelAsync();
            await Program.WaitAsync(Limit);
            Twin.Dispose();
            _stop.Dispose();
        }
    }

    private static async Task<(DriverTwin Driver, Robot Bot, ConcurrentQueue<int> Executed)> ConnectAsync(Action<Robot>? configure = null)
    {
        var driver = new DriverTwin(null);
        await EventuallyAsync(() => driver.Twin.EkiPort("machina_kuka_server") > 0 || driver.Program.IsCompleted, "the driver to listen");
        Assert.False(driver.Program.IsCompleted, driver.Twin.Error);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await ConnectRobotAsync("KrlTwinBot", "KUKA", driver.Twin.EkiPort("machina_kuka_server"), b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            configure?.Invoke(b);
        });
        return (driver, bot, executed);
    }

    [Fact]
    public async Task UnchangedDriver_StreamsHelloRobotAnd10000Actions_ExactlyOnceAndInOrder()
    {
        var (driver, bot, executed) = await ConnectAsync();
        await using (driver)
        {
            ReferencePrograms.HelloRobot(bot);
            bot.TransformTo(400, 0, 500, -1, 0, 0, 0, 1, 0);
            for (int i = 0; i < 10_000; i++)
            {
                bot.Move(0, i % 2 == 0 ? 10 : -10, 0);
            }
            // A bound, not a speed test (the benchmark measures speed): 10^4 moves through the interpreter on a loaded machine.
            await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromMinutes(3));
            await bot.FlushEventsAsync().WaitAsync(TimeSpan.FromMinutes(1));

            int total = 8 + 10_000;
            Assert.Equal(Enumerable.Range(1, total), executed);
            List<TwinTraceEntry> motions = [.. driver.Twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Motion)];
            Assert.Equal(1 + 4 + 1 + 10_000, motions.Count); // BCO run, 4 Hello Robot motions, TransformTo, the moves
            Assert.Equal(400, motions[^1].Tcp.Position.X, 3);
            Assert.Equal(0, motions[^1].Tcp.Position.Y, 3);
            Assert.Equal(500, motions[^1].Tcp.Position.Z, 3);
            Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), motions[4].Joints);
            Assert.Contains("NOTIFY Machina 1: Hello Robot!", driver.Twin.Pendant.Lines);
            Assert.True(driver.Twin.Clock.Seconds > 2 + 10_000 * 0.1, $"{driver.Twin.Clock.Seconds} s"); // WAIT SEC 2, then 10 mm at 0.1 m/s each (not real-time here)
            Assert.Equal(KrlProgramState.Running, driver.Twin.State);
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task AxisTargetBeyondASoftwareLimitSwitch_DriverSendsF_HostReportsTheActionFailed_ProgramHalts()
    {
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var (driver, bot, executed) = await ConnectAsync(b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        await using (driver)
        {
            bot.Do("AxesTo(10, -90, 90, 0, 90, 0); AxesTo(175, -90, 90, 0, 90, 0); AxesTo(0, -90, 90, 0, 90, 0);");
            ActionFailedArgs e = await failed.Task.WaitAsync(Limit);
            await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync().WaitAsync(Limit));
            await bot.FlushEventsAsync().WaitAsync(Limit);

            Assert.Equal(2, e.Action.Id);
            Assert.Equal("Software limit switch: an axis target is beyond its software limits.", e.Reason);
            Assert.Equal("2", e.Failure.ControllerCode);
            Assert.Equal([1], executed);
            Assert.Equal(new[] { 3 }, e.CancelledActions.Select(a => a.Id));
            Assert.Equal(KrlProgramState.Stopped, await driver.Program.WaitAsync(Limit));
            Assert.Equal(10, driver.Twin.Arm.Joints.J1, 6);
            Assert.Equal("QUIT Machina 2: Software limit switch: an axis target is beyond its software limits.", driver.Twin.Pendant.Lines[^1]);
            await bot.DisconnectAsync();
        }
    }
}
