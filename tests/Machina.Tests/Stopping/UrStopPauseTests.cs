using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop / Pause / Resume on the UR twin that runs the unchanged driver script, through its dashboard: a long slow move
/// (10 mm/s, seconds of margin) is stopped or paused once the arm has left its start, so the arm is short of the target
/// whatever the load; a stopped arm does not move again, a paused one goes on to the exact target after Resume.
/// </summary>
public class UrStopPauseTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task Stop_HaltsTheMoveWhereTheArmIs_FailsItAndCancelsWhatFollows_NothingAfterRuns()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions());
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            Vector start = controller.State.Position;
            Vector target = start + new Vector(0, 0, -200);
            bot.Do("SpeedTo(10); Move(0, 0, -200); WriteDigital(2, true);");
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
            Assert.DoesNotContain("2", controller.State.DigitalOutputs.Keys);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Pause_HoldsTheMoveShortOfItsTarget_ResumeFinishesItExactlyOnce()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions());
        var executed = new ConcurrentQueue<int>();
        var stopped = new TaskCompletionSource<ControllerStoppedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ControllerStopped += (_, e) => stopped.TrySetResult(e);
        });
        try
        {
            Vector start = controller.State.Position;
            Vector target = start + new Vector(0, 0, -100);
            bot.Do("SpeedTo(10); Move(0, 0, -100); WriteDigital(2, true);");
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

            Assert.True(controller.State.Position.IsSimilar(target, 1e-3), controller.State.Position.ToString());
            Assert.Equal([1, 2, 3], executed);
            Assert.Contains("2", controller.State.DigitalOutputs.Keys);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task StopAndPause_OnAKukaRobot_AreNotSupportedYet_WithAClearMessage()
    {
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync();
        (Robot bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller);
        try
        {
            var stop = await Assert.ThrowsAsync<NotSupportedException>(() => bot.StopAsync());
            Assert.Equal("Stopping the motion is not available for this brand yet (UR and ABB only); ClearPendingActions drops what is not sent.", stop.Message);
            var pause = await Assert.ThrowsAsync<NotSupportedException>(() => bot.PauseAsync());
            Assert.Equal("Pausing is not available for this brand yet (UR and ABB only); ClearPendingActions drops what is not sent.", pause.Message);
            Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public void Stop_Offline_IsRefused()
    {
        var bot = Robot.Create("T", "UR");
        var e = Assert.Throws<InvalidOperationException>(() => bot.Stop());
        Assert.Equal("Cannot stop while the robot is offline; call ControlMode(\"online\") first.", e.Message);
    }
}
