using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop / Pause / Resume on the ABB twin that runs the unchanged RAPID driver and monitor: the monitor task takes the command
/// out of band (StopMove / StartMove \AllMotionTasks); on a stop the driver's interrupt on machinaStopRequest clears the path and
/// fails the move under way. A long slow move (10 mm/s) is stopped or paused once the arm has left its start, so the arm is short
/// of the target whatever the load.
/// </summary>
public class AbbStopPauseTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    private static async Task<VirtualAbbController> StartAsync()
    {
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions());
        await controller.StartAsync().WaitAsync(Long);
        return controller;
    }

    [Fact]
    public async Task Stop_HaltsTheMoveWhereTheArmIs_FailsItAndCancelsWhatFollows_NothingAfterRuns()
    {
        await using VirtualAbbController controller = await StartAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            Vector start = controller.State.Position;
            Vector target = start + new Vector(0, 0, -200);
            bot.Do("SpeedTo(10); Move(0, 0, -200); WriteDigital(\"DO_2\", true);");
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);

            await bot.StopAsync().WaitAsync(Long);
            ActionFailedArgs e = await failed.Task.WaitAsync(Long);

            Vector at = controller.State.Position;
            Assert.True(Vector.Distance(at, start) > 5, at.ToString());
            Assert.True(Vector.Distance(at, target) > 50, $"the arm reached {at}, too near the target {target}");
            Assert.IsType<ActionTranslation>(e.Action);
            Assert.Equal(2, e.Action.Id);
            Assert.Equal("stopped by the user (Robot.Stop): the motion stopped where the arm was and nothing after it ran.", e.Reason);
            Assert.Equal("stopped", e.Failure.ControllerCode);
            Assert.Equal([3], e.CancelledActions.Select(a => a.Id));
            Assert.False(bot.IsConnected);

            // Stopped means stopped: a moment later the arm is where it was, and the output after the move was never set.
            await Task.Delay(300);
            Assert.True(Vector.Distance(controller.State.Position, at) < 0.01, controller.State.Position.ToString());
            Assert.DoesNotContain("DO_2", controller.State.DigitalOutputs.Keys);

            // The driver keeps serving: a new connection goes on from where the arm stopped, and what was dropped stays dropped.
            Robot again = await OnlineTestSupport.ConnectAsync(controller);
            try
            {
                again.Do("SpeedTo(200); Move(0, 0, 10);");
                await again.WaitForCompletionAsync().WaitAsync(Long);
                Assert.True(controller.State.Position.IsSimilar(at + new Vector(0, 0, 10), 1e-2), controller.State.Position.ToString());
                Assert.DoesNotContain("DO_2", controller.State.DigitalOutputs.Keys);
            }
            finally
            {
                await again.DisconnectAsync();
            }
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Pause_HoldsTheMoveShortOfItsTarget_ResumeFinishesItExactlyOnce()
    {
        await using VirtualAbbController controller = await StartAsync();
        var executed = new ConcurrentQueue<int>();
        var stopped = new TaskCompletionSource<ControllerStoppedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ControllerStopped += (_, e) => stopped.TrySetResult(e);
        });
        try
        {
            Vector start = controller.State.Position;
            Vector target = start + new Vector(0, 0, -100);
            bot.Do("SpeedTo(10); Move(0, 0, -100); WriteDigital(\"DO_2\", true);");
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);

            await bot.PauseAsync().WaitAsync(Long);
            ControllerStoppedArgs pause = await stopped.Task.WaitAsync(Long);
            Assert.Equal("Paused by the user (Robot.Pause): the motion holds where the arm is; call Resume to go on.", pause.Reason!.Message);
            Assert.Equal(ConnectionState.Stopped, bot.ConnectionState);
            Vector held = controller.State.Position;
            await Task.Delay(300);
            Assert.True(Vector.Distance(controller.State.Position, held) < 0.01, $"the arm moved from {held} to {controller.State.Position} while paused");
            Assert.True(Vector.Distance(held, target) > 20, $"the arm reached {held}, too near the target {target}");
            Assert.DoesNotContain(2, executed);

            await bot.ResumeAsync().WaitAsync(Long);
            await bot.WaitForCompletionAsync().WaitAsync(Long);

            Assert.True(controller.State.Position.IsSimilar(target, 1e-2), controller.State.Position.ToString());
            Assert.Equal([1, 2, 3], executed);
            Assert.True(controller.State.DigitalOutputs["DO_2"]);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
