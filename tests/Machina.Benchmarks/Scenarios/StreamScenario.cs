using Machina.Simulation;

namespace Machina.Benchmarks;

/// <summary>
/// Streams moves online to a virtual controller (ABB, or UR with <paramref name="ur"/>) on loopback that executes every
/// instruction at once, and times from the first issued move until the controller has acknowledged the last one. With
/// <paramref name="wideWindow"/> the release window is widened (100 actions per block) to show what the link can carry;
/// otherwise the defaults are used. With <paramref name="twin"/> the virtual UR runs the driver script on its URScript interpreter; the
/// virtual ABB always runs the driver and monitor modules on its RAPID interpreter (its C# imitation is gone).
/// </summary>
internal sealed class StreamScenario(bool wideWindow, bool ur = false, bool twin = false) : Scenario
{
    private IAsyncDisposable? _controller;
    private Robot? _bot;

    public override string Name => (ur ? "stream-ur" : "stream") + (twin ? "-twin" : "") + (wideWindow ? "-wide" : "");

    public override string Title => $"Stream moves to the virtual {(ur ? "UR" : "ABB")} controller{TwinText}, instant execution, "
        + (wideWindow ? "window 100/100" : "default window");

    private string TwinText => !ur ? " running the driver modules" : twin ? " running the driver script" : "";

    public override int TargetSize => 100_000;

    public override IReadOnlyList<int> ScalingSizes => [10_000, 100_000];

    public override Target Target => Catalog.StreamTarget;

    public override bool MultiThreaded => true;

    public override Func<object?> Prepare(int size)
    {
        int port;
        if (ur)
        {
            var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
            controller.StartAsync().GetAwaiter().GetResult();
            (_controller, port) = (controller, controller.Port);
        }
        else
        {
            // The RAPID twin runs the driver modules on a model; an IRB 1600 reaches every point of the square below.
            var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true, Model = RobotModels.Get("IRB 1600-8/1.45") });
            controller.StartAsync().GetAwaiter().GetResult();
            (_controller, port) = (controller, controller.Port);
        }
        var bot = Robot.Create("Stream", ur ? "UR" : "ABB");
        _bot = bot;
        bot.ControlMode("online");
        if (wideWindow)
        {
            bot.BlockSize = 100;
            bot.PendingCount = 100;
        }
        bot.ConnectAsync("127.0.0.1", port).GetAwaiter().GetResult();
        bot.SpeedTo(1000);
        if (ur)
        {
            bot.MoveTo(300, -300, 400);
        }
        else
        {
            bot.MoveTo(300, 0, 500);
        }
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
