using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// A UR stop awaited (dashboard <c>stop</c>, <c>load</c>, <c>power off</c>, the primary <c>stop program</c>, an RTDE watchdog's
/// <c>stop</c>) holds no thread while the program it stops winds down: its task completes when the program's thread has ended,
/// and the caller is free before that. The program is held as it ends (its <c>Ending</c> hook) to make the wait long and sure.
/// </summary>
public sealed class UrTwinAwaitedStopTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task StopOnPathAsync_ReturnsWhileTheProgramEnds_CompletesOnceItEnded()
    {
        using var twin = new UrTwinController(new UrTwinOptions { RealTime = true });
        twin.StopTimeout = Bound;
        using var release = new ManualResetEventSlim();
        var ending = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        twin.Ending = _ =>
        {
            ending.TrySetResult();
            release.Wait(Bound);
        };
        twin.Receive("def moving():\n  textmsg(\"moving\")\n  while True:\n    movej([0, -1.57, 1.57, -1.57, -1.57, 0], a=1, v=0.05)\n    movej([0.5, -1.57, 1.57, -1.57, -1.57, 0], a=1, v=0.05)\n  end\nend\n");
        await Eventually.TrueAsync(() => twin.Motion is not null, "the program to be moving", Bound);

        Task stop = twin.StopOnPathAsync(CancellationToken.None);
        await ending.Task.WaitAsync(Bound); // the program's thread is in its end, held there
        Assert.False(stop.IsCompleted, "the stop completed before the program's thread ended");
        Assert.Equal(UrProgramState.Running, twin.State); // its end not yet recorded either
        Assert.True(twin.IsHeld);
        release.Set();
        await stop.WaitAsync(Bound);

        Assert.Equal(UrProgramState.Stopped, twin.State);
        Assert.False(twin.IsHeld); // the hold used to stop on the path is cleared
        Assert.Null(twin.Motion);
    }

    [Fact]
    public async Task DashboardStop_AnsweredOnceTheProgramEnded_WhileAnotherConnectionIsServed()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions());
        await controller.StartAsync();
        controller.Twin.StopTimeout = Bound;
        using var release = new ManualResetEventSlim();
        var ending = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        controller.Twin.Ending = _ =>
        {
            ending.TrySetResult();
            release.Wait(Bound);
        };
        controller.Twin.Receive("def waiting():\n  while True:\n    sleep(1)\n  end\nend\n");
        using var first = await UrSimDashboardTests.DashboardAsync(controller.DashboardPort);
        using var second = await UrSimDashboardTests.DashboardAsync(controller.DashboardPort);
        Assert.Equal("PLAYING waiting", await UrSimDashboardTests.AskAsync(second, "programState"));

        await first.Client.GetStream().WriteAsync("stop\n"u8.ToArray());
        Task<string?> stopped = first.Reader.ReadLineAsync();
        await ending.Task.WaitAsync(Bound);
        // Held to stop on its path, its end not yet recorded (as before the stop was awaited).
        Assert.Equal("PAUSED waiting", await UrSimDashboardTests.AskAsync(second, "programState"));
        Assert.False(stopped.IsCompleted, "the stop was answered before the program ended");
        release.Set();

        Assert.Equal("Stopped", await stopped.WaitAsync(Bound));
        Assert.Equal("STOPPED waiting", await UrSimDashboardTests.AskAsync(second, "programState"));
        Assert.False(controller.IsProgramRunning);
    }
}
