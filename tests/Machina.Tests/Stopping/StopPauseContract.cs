using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Stopping;

/// <summary>
/// The contract of Robot.Stop / Pause / Resume on every brand's twin that runs the brand's unchanged driver: a long slow move
/// (10 mm/s, seconds of margin) is stopped or paused once the arm has left its start, so the arm is short of the target
/// whatever the load. Stop: the move fails where the arm is, the action after it is cancelled, one ActionFailed "stopped by the
/// user", nothing moves after and (where the driver keeps serving) a new connection runs. Pause holds where the arm is; Resume
/// plays again, each action exactly once. A brand's class says how to start its controller, connect and name an output.
/// </summary>
public abstract class StopPauseContract<TController, TState>
    where TController : VirtualController<TState>
    where TState : VirtualRobotState
{
    /// <summary>How long any one wait of these tests may take (a loaded CI machine is slow, never stuck).</summary>
    protected static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    /// <summary>A real-time virtual controller of the brand, started on loopback.</summary>
    protected abstract Task<TController> StartAsync();

    /// <summary>A robot of the brand connected to <paramref name="controller"/>, set up by <paramref name="configure"/> first.</summary>
    protected abstract Task<Robot> ConnectAsync(TController controller, Action<Robot>? configure = null);

    /// <summary>The action that sets the output after the move, e.g. <c>WriteDigital(2, true);</c>.</summary>
    protected abstract string WriteOutput { get; }

    /// <summary>The name the controller's state gives that output.</summary>
    protected abstract string OutputKey { get; }

    /// <summary>How near the target a resumed move must end (mm).</summary>
    protected virtual double ArrivalTolerance => 1e-2;

    /// <summary>True when the driver keeps serving after a stop, so a new connection runs on from where the arm stopped.</summary>
    protected virtual bool RunsAgainAfterStop => true;

    /// <summary>Awaits <paramref name="control"/>; when it fails, the failure names the controller's pendant and error logs.</summary>
    private static async Task WithLogsAsync(TController controller, Task control)
    {
        try
        {
            await control;
        }
        catch (MachinaException e)
        {
            throw new Xunit.Sdk.XunitException($"{e.GetType().Name}: {e.Message}\npendant: {string.Join(" | ", controller.PendantMessages)}\nerrors: {string.Join(" | ", controller.Errors)}");
        }
    }

    [Fact]
    public async Task Stop_HaltsTheMoveWhereTheArmIs_FailsItAndCancelsWhatFollows_NothingAfterRuns()
    {
        await using TController controller = await StartAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        Robot bot = await ConnectAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            Vector start = controller.State.Position;
            Vector target = start + new Vector(0, 0, -200);
            bot.Do("SpeedTo(10); Move(0, 0, -200); " + WriteOutput);
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);

            await WithLogsAsync(controller, bot.StopAsync().WaitAsync(Long));
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
            Assert.DoesNotContain(OutputKey, controller.State.DigitalOutputs.Keys);

            if (RunsAgainAfterStop)
            {
                // The driver keeps serving: a new connection goes on from where the arm stopped, and what was dropped stays dropped.
                Robot again = await ConnectAsync(controller);
                try
                {
                    again.Do("SpeedTo(200); Move(0, 0, 10);");
                    await WithLogsAsync(controller, again.WaitForCompletionAsync().WaitAsync(Long));
                    Assert.True(controller.State.Position.IsSimilar(at + new Vector(0, 0, 10), 1e-2), controller.State.Position.ToString());
                    Assert.DoesNotContain(OutputKey, controller.State.DigitalOutputs.Keys);
                }
                finally
                {
                    await again.DisconnectAsync();
                }
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
        await using TController controller = await StartAsync();
        var executed = new ConcurrentQueue<int>();
        var stopped = new TaskCompletionSource<ControllerStoppedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var log = new ConcurrentQueue<LogEntry>();
        Robot bot = await ConnectAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ControllerStopped += (_, e) => stopped.TrySetResult(e);
            b.Logger.Logged += (_, e) => log.Enqueue(e);
        });
        try
        {
            Vector start = controller.State.Position;
            Vector target = start + new Vector(0, 0, -100);
            bot.Do("SpeedTo(10); Move(0, 0, -100); " + WriteOutput);
            await Eventually.TrueAsync(() => Vector.Distance(controller.State.Position, start) > 5, "the arm to leave its start", Long);

            await WithLogsAsync(controller, bot.PauseAsync().WaitAsync(Long));
            ControllerStoppedArgs pause = await stopped.Task.WaitAsync(Long);
            Assert.Equal("Paused by the user (Robot.Pause): the motion holds where the arm is; call Resume to go on.", pause.Reason!.Message);
            Assert.Equal(ConnectionState.Stopped, bot.ConnectionState);
            Vector held = controller.State.Position;
            await Task.Delay(300);
            Assert.True(Vector.Distance(controller.State.Position, held) < 0.01, $"the arm moved from {held} to {controller.State.Position} while paused");
            Assert.True(Vector.Distance(held, target) > 20, $"the arm reached {held}, too near the target {target}");
            Assert.DoesNotContain(2, executed);
            // A pause the user asked for is information, not an error (issue 46).
            Assert.Contains(log, e => e.Level == LogLevel.INFO && e.Message.Contains("paused: Paused by the user", StringComparison.Ordinal));
            Assert.DoesNotContain(log, e => e.Level == LogLevel.ERROR);

            await WithLogsAsync(controller, bot.ResumeAsync().WaitAsync(Long));
            await bot.WaitForCompletionAsync().WaitAsync(Long);

            Assert.True(controller.State.Position.IsSimilar(target, ArrivalTolerance), controller.State.Position.ToString());
            Assert.Equal([1, 2, 3], executed);
            Assert.True(controller.State.DigitalOutputs[OutputKey]);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
