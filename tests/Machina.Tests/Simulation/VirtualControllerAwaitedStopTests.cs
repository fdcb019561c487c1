using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// A virtual controller's own stop (<see cref="VirtualController{TState}.StopAsync(CancellationToken)"/>) awaits its program's end
/// instead of joining it: the stop's task stays incomplete while the program's thread is held in its end (its <c>Ending</c> hook
/// holds it there, to make the wait long and sure), the caller is free meanwhile, and a token ends the caller's wait early while
/// the controller is stopped all the same.
/// </summary>
public sealed class VirtualControllerAwaitedStopTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task StopAsync_WhileTheProgramWindsDown_ReturnsAtOnce_CompletesOnceItEnded()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions());
        await controller.StartAsync();
        using var release = new ManualResetEventSlim();
        var ending = HoldInItsEnd(controller, release);

        Task stop = controller.StopAsync(CancellationToken.None);
        await ending.WaitAsync(Bound); // the program's thread is in its end, held there
        Assert.False(stop.IsCompleted, "the stop completed before the program's thread ended");
        Assert.False(controller.IsRunning);
        release.Set();
        await stop.WaitAsync(Bound);

        Assert.Equal(UrProgramState.Stopped, controller.Twin.State);
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task StopAsync_CancelledWhileTheProgramWindsDown_EndsTheWait_TheControllerIsStoppedAllTheSame()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions());
        await controller.StartAsync();
        using var release = new ManualResetEventSlim();
        var ending = HoldInItsEnd(controller, release);
        using var cancel = new CancellationTokenSource();

        Task stop = controller.StopAsync(cancel.Token);
        await ending.WaitAsync(Bound);
        await cancel.CancelAsync();
        // Ends while the program is still held in its end: nothing joins it (cancelled, or done when nothing else was left).
        try
        {
            await stop.WaitAsync(Bound);
        }
        catch (OperationCanceledException)
        {
        }
        Assert.Equal(UrProgramState.Running, controller.Twin.State); // its end not yet recorded
        Assert.False(controller.IsRunning);

        release.Set(); // the program ends by itself (nothing waits for it now); a second stop waits for the loops left
        await Eventually.TrueAsync(() => controller.Twin.State == UrProgramState.Stopped, "the program to end by itself", Bound);
        await controller.StopAsync().WaitAsync(Bound);
    }

    /// <summary>Runs a program whose thread, once stopped, holds in its end until <paramref name="release"/>; the task completes when it is held.</summary>
    private static Task HoldInItsEnd(VirtualUrController controller, ManualResetEventSlim release)
    {
        controller.Twin.StopTimeout = Bound;
        var ending = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        controller.Twin.Ending = _ =>
        {
            ending.TrySetResult();
            release.Wait(Bound);
        };
        controller.Twin.Receive("def waiting():\n  while True:\n    sleep(1)\n  end\nend\n");
        return ending.Task;
    }
}
