using Machina.Simulation.Krl;

namespace Machina.Benchmarks;

/// <summary>
/// Streams moves online to the KRL twin running Machina's unchanged KRL driver (drivers/kuka) on EthernetKRL over loopback,
/// not in real time, and times from the first issued move until the driver has acknowledged the last one (issue 23). With
/// <paramref name="wideWindow"/> the robot sends blocks of 100 with 100 pending (<c>stream-kuka-twin</c>), otherwise it keeps
/// Machina's default window (<c>stream-kuka-twin-default</c>).
/// </summary>
internal sealed class KrlTwinStreamScenario(bool wideWindow = true) : Scenario
{
    private KrlTwinController? _twin;
    private CancellationTokenSource? _stop;
    private Task? _program;
    private Robot? _bot;

    public override string Name => wideWindow ? "stream-kuka-twin" : "stream-kuka-twin-default";

    public override string Title => "Stream moves to the KRL twin running the KRL driver on EthernetKRL, instant execution, "
        + (wideWindow ? "window 100/100" : "default window");

    public override int TargetSize => 100_000;

    public override IReadOnlyList<int> ScalingSizes => [10_000, 100_000];

    public override Target Target => Catalog.StreamTarget;

    public override bool MultiThreaded => true;

    private static string Fill(string file) => KukaDriverModules.Read(file)
        .Replace("{{HOSTNAME}}", "127.0.0.1", StringComparison.Ordinal).Replace("{{PORT}}", "0", StringComparison.Ordinal)
        .Replace("{{ADVANCE}}", "3", StringComparison.Ordinal);

    public override Func<object?> Prepare(int size)
    {
        var twin = new KrlTwinController();
        twin.AddEkiConfiguration("machina_kuka_server", Fill("machina_kuka_server.xml"));
        twin.Load(("machina_kuka_driver.src", Fill("machina_kuka_driver.src")), ("machina_kuka_driver.dat", Fill("machina_kuka_driver.dat")));
        _twin = twin;
        _stop = new CancellationTokenSource();
        CancellationToken token = _stop.Token;
        _program = Task.Factory.StartNew(() => twin.Run("machina_kuka_driver", token), token, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (twin.EkiPort("machina_kuka_server") == 0)
        {
            if (waited.Elapsed > TimeSpan.FromSeconds(30) || _program.IsCompleted)
            {
                throw new InvalidOperationException($"The KRL driver did not start listening: {twin.Error}");
            }
            Thread.Sleep(5);
        }
        var bot = Robot.Create("Stream", "KUKA");
        _bot = bot;
        bot.ControlMode("online");
        if (wideWindow)
        {
            bot.BlockSize = 100;
            bot.PendingCount = 100;
        }
        bot.ConnectAsync("127.0.0.1", twin.EkiPort("machina_kuka_server")).GetAwaiter().GetResult();
        bot.SpeedTo(1000);
        bot.TransformTo(400, 0, 500, -1, 0, 0, 0, 1, 0);
        Vector[] steps = [new(10, 0, 0), new(0, 10, 0), new(-10, 0, 0), new(0, -10, 0)];
        return () =>
        {
            for (int i = 0; i < size; i++)
            {
                bot.Move(steps[i & 3]);
            }
            // Generous: 1 ms per action plus a minute, so a stalled link fails the scenario instead of hanging the harness.
            using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(1) + TimeSpan.FromMilliseconds(size));
            bot.WaitForCompletionAsync(timeout.Token).GetAwaiter().GetResult();
            return null;
        };
    }

    public override void Cleanup()
    {
        _bot?.DisconnectAsync().GetAwaiter().GetResult();
        _stop?.Cancel();
        _program?.Wait(TimeSpan.FromSeconds(30));
        _twin?.Dispose();
        _stop?.Dispose();
        (_bot, _twin, _stop, _program) = (null, null, null, null);
    }
}
