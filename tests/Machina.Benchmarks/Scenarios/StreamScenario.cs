using Machina.Simulation;

namespace Machina.Benchmarks;

/// <summary>
/// Streams moves online to a virtual ABB controller on loopback that executes every instruction at once, and times from
/// the first issued move until the controller has acknowledged the last one. With <paramref name="wideWindow"/> the
/// release window is widened (100 actions per block) to show what the link can carry; otherwise the defaults are used.
/// </summary>
internal sealed class StreamScenario(bool wideWindow) : Scenario
{
    private VirtualAbbController? _controller;
    private Robot? _bot;

    public override string Name => wideWindow ? "stream-wide" : "stream";

    public override string Title => wideWindow
        ? "Stream moves to the virtual ABB controller, instant execution, window 100/100"
        : "Stream moves to the virtual ABB controller, instant execution, default window";

    public override int TargetSize => 100_000;

    public override IReadOnlyList<int> ScalingSizes => [10_000, 100_000];

    public override Target Target => Catalog.StreamTarget;

    public override bool MultiThreaded => true;

    public override Func<object?> Prepare(int size)
    {
        _controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true });
        _controller.StartAsync().GetAwaiter().GetResult();
        var bot = Robot.Create("Stream", "ABB");
        _bot = bot;
        bot.ControlMode("online");
        if (wideWindow)
        {
            bot.BlockSize = 100;
            bot.PendingCount = 100;
        }
        bot.ConnectAsync("127.0.0.1", _controller.Port).GetAwaiter().GetResult();
        bot.SpeedTo(1000);
        bot.MoveTo(300, 0, 500);
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
        _controller?.DisposeAsync().AsTask().GetAwaiter().GetResult();
        _bot = null;
        _controller = null;
    }
}
