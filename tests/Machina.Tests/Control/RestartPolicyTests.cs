namespace Machina.Tests.Control;

/// <summary>
/// The session's rule for a controller restart (issue 40), on a fake driver: a controller whose progress was reset after this
/// robot saw an acknowledgement does not know the actions in flight, so they end failed, unsent; the actions never sent are
/// sent. A controller that says it ran nothing before any acknowledgement reached the host gets them again.
/// </summary>
public class RestartPolicyTests
{
    private static (Robot Bot, FakeDriver First, List<int> Executed, List<ActionFailedArgs> Failed, List<LogEntry> Log) Start(FakeDriver next)
    {
        var first = new FakeDriver();
        var drivers = new Queue<FakeDriver>([first, next]);
        var bot = Robot.Create("Restarted", "ABB");
        bot.DriverFactory = () => drivers.Dequeue();
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        var executed = new List<int>();
        var failed = new List<ActionFailedArgs>();
        var log = new List<LogEntry>();
        bot.ActionExecuted += (_, e) => executed.Add(e.LastAction.Id);
        bot.ActionFailed += (_, e) => failed.Add(e);
        bot.Logger.AddSink(log.Add, LogLevel.WARNING);
        bot.MoveTo(400, 0, 400);
        for (int i = 1; i < 12; i++)
        {
            bot.Move(0, 0, 10);
        }
        return (bot, first, executed, failed, log);
    }

    [Fact]
    public async Task Reconnect_ProgressReset_InFlightFailUnsent_NeverSentSent_WaitThrowsOnce()
    {
        var second = new FakeDriver(autoAcknowledge: true);
        var (bot, first, executed, failed, log) = Start(second);
        Assert.Equal(8, first.Sent.Count); // the first block
        first.Ack(2);
        first.Listener!.OnFault(new RobotConnectionException("socket closed"));

        second.Handshake = second.Handshake with { Version = "1.6.0", Position = new Vector(400, 0, 500), Progress = new DeviceProgress(0, 0) };
        bot.Connect("127.0.0.1", 7000);
        var thrown = await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout));
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout); // once only
        OnlineRobot.Flush(bot);

        Assert.Equal([1, 2, 9, 10, 11, 12], executed);
        Assert.Equal(Enumerable.Range(9, 4), second.Sent.Select(a => a.Id)); // 3-8 are never sent again
        Assert.Equal(Enumerable.Range(3, 6), failed.Select(f => f.Action.Id));
        Assert.All(failed, f => Assert.Equal(("the controller restarted; this action may or may not have run", "restarted"), (f.Reason, f.Failure.ControllerCode)));
        Assert.Equal("Move(0,0,10); (id 3) was not sent again: the controller restarted; this action may or may not have run. Check the robot, then issue it again if it must run.",
            failed[0].Failure.Message);
        Assert.Equal(3, thrown.Action.Id);
        Assert.StartsWith("6 actions (ids 3-8) were not sent again: the controller restarted", thrown.Message, StringComparison.Ordinal);
        LogEntry warning = Assert.Single(log, e => e.Level == LogLevel.WARNING);
        Assert.StartsWith("The controller restarted (its progress is 0 executed, 0 received): the 6 actions sent before the restart and not confirmed (ids 3-8) "
            + "may or may not have run and are not sent again", warning.Message, StringComparison.Ordinal);
        Assert.EndsWith("The 4 actions never sent are sent now.", warning.Message, StringComparison.Ordinal);
        Assert.Equal(new Vector(400, 0, 540), bot.GetExecutedState().Position); // the 4 never sent, from where the controller is
        Assert.Empty(bot.GetPendingActions());
    }

    [Fact]
    public async Task Reconnect_ProgressReset_ResendPolicy_InFlightSentAgain()
    {
        var second = new FakeDriver(autoAcknowledge: true);
        var (bot, first, executed, failed, log) = Start(second);
        bot.ResendAfterControllerRestart = true;
        first.Ack(2);
        first.Listener!.OnFault(new RobotConnectionException("socket closed"));

        second.Handshake = second.Handshake with { Version = "1.6.0", Progress = new DeviceProgress(0, 0) };
        bot.Connect("127.0.0.1", 7000);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        OnlineRobot.Flush(bot);

        Assert.Equal(Enumerable.Range(1, 12), executed);
        Assert.Equal(Enumerable.Range(3, 10), second.Sent.Select(a => a.Id));
        Assert.Empty(failed);
        Assert.Contains("the 6 actions sent before the restart and not confirmed (ids 3-8) are sent again (ResendAfterControllerRestart)",
            Assert.Single(log, e => e.Level == LogLevel.WARNING).Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Reconnect_NothingRanNorAcknowledged_InFlightSentAgain()
    {
        var second = new FakeDriver(autoAcknowledge: true);
        var (bot, first, executed, failed, log) = Start(second);
        first.Listener!.OnFault(new RobotConnectionException("socket closed"));

        second.Handshake = second.Handshake with { Version = "1.6.0", Progress = new DeviceProgress(0, 0) };
        bot.Connect("127.0.0.1", 7000);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineRobot.Timeout);
        OnlineRobot.Flush(bot);

        Assert.Equal(Enumerable.Range(1, 12), executed);
        Assert.Empty(failed);
        Assert.StartsWith("The controller reports that it ran nothing, and none of the 8 actions", Assert.Single(log, e => e.Level == LogLevel.WARNING).Message, StringComparison.Ordinal);
    }
}
