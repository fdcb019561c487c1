using System.Collections.Concurrent;
using Machina.Tests.Online;

namespace Machina.Tests.Stopping;

/// <summary>
/// Robot.Stop on ABB when the driver task's report of the stopped move (<c>$26 id 4;</c>, from its interrupt on
/// machinaStopRequest) reaches the host before the monitor task's answer to "S" (<c>$28 3;</c>): the monitor sets the request
/// and then answers, so a loaded controller may let the driver's task run first. The host applies the report as the stop and
/// closes the link, so the answer is never read. A scripted controller plays that order without timing (it answers "S" only
/// once the host has closed the driver link). Before session 36 Robot.Stop then waited for the answer until its 10 s limit and
/// threw "did not answer the stop command", although the robot had stopped and ActionFailed had been raised
/// (the bridge's side: <see cref="Machina.Tests.Bridge.BridgeStopReportFirstTests"/>).
/// </summary>
public class AbbStopReportFirstTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    internal const string Program = "SpeedTo(10); Move(0, 0, -200); WriteDigital(\"DO_2\", true);";

    [Fact]
    public async Task Stop_DriverReportsTheStoppedMoveBeforeTheMonitorAnswers_StopReturnsAndTheMoveFailsStopped()
    {
        await using var controller = ScriptedAbbController.Start();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Task<Robot> connecting = OnlineTestSupport.ConnectRobotAsync("HelloRobot", "ABB", controller.Port, b =>
        {
            b.ActionFailed += (_, e) => failed.TrySetResult(e);
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        });
        await controller.AcceptAsync();
        Robot bot = await connecting.WaitAsync(Long);
        try
        {
            bot.Do(Program);
            Assert.Matches(@"^@1 4 [^;]*;@2 1 [^;]*;@3 10 ", await controller.ReadDriverUntilAsync("@3 10 "));
            await controller.WriteDriverAsync("@1 4;"); // the speed is set; the move runs

            Task stopping = bot.StopAsync();
            await controller.StopReportFirstAsync(2);

            await stopping.WaitAsync(Long); // threw "did not answer the stop command within 10 s" before
            ActionFailedArgs e = await failed.Task.WaitAsync(Long);
            Assert.Equal(2, e.Action.Id);
            Assert.Equal("stopped by the user (Robot.Stop): the motion stopped where the arm was and nothing after it ran.", e.Reason);
            Assert.Equal("stopped", e.Failure.ControllerCode);
            Assert.Equal([3], e.CancelledActions.Select(a => a.Id));
            Assert.False(bot.IsConnected);
            await bot.FlushEventsAsync();
            Assert.Equal([1], executed);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
