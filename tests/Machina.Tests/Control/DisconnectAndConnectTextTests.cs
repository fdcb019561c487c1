namespace Machina.Tests.Control;

/// <summary>
/// What a new user meets at the ends of a session (issue 46): Disconnect right after issuing says what was left, Connect() with
/// no arguments says what it tried and what to pass, and a controller's empty error code is not shown as "(code )".
/// </summary>
public class DisconnectAndConnectTextTests
{
    [Fact]
    public void Disconnect_RightAfterIssuing_WarnsHowManyActionsWereNotExecuted()
    {
        var driver = new FakeDriver();
        Robot bot = OnlineRobot.Create(driver);
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);
        bot.BlockSize = 1;
        bot.PendingCount = 1;

        bot.Do("MoveTo(300, 0, 400); Move(0, 0, 10); Move(0, 10, 0);");
        bot.Disconnect();
        OnlineRobot.Flush(bot);

        LogEntry warning = Assert.Single(log, e => e.Level == LogLevel.WARNING);
        Assert.Equal("Disconnected from \"Online\" with 3 actions not executed (1 sent and not confirmed, which the robot may still run; "
            + "2 never sent). Call WaitForCompletion before Disconnect to let the robot finish them.", warning.Message);
    }

    [Fact]
    public void Disconnect_AfterEverythingRan_SaysNothingMore()
    {
        var driver = new FakeDriver(autoAcknowledge: true);
        Robot bot = OnlineRobot.Create(driver);
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);

        bot.Do("MoveTo(300, 0, 400);");
        Assert.True(bot.WaitForCompletion(OnlineRobot.Timeout));
        bot.Disconnect();
        OnlineRobot.Flush(bot);

        Assert.DoesNotContain(log, e => e.Level is LogLevel.WARNING or LogLevel.ERROR);
    }

    [Fact]
    public void ConnectWithNoArguments_NothingAnswers_MachinaExceptionNamesWhatItTriedAndWhatToPass()
    {
        var driver = new FakeDriver { DuringConnect = _ => throw new RobotConnectionException("Could not connect to 127.0.0.1:7000: Connection refused. Is the driver running there?") };
        Robot bot = OnlineRobot.Create(driver, connect: false);

        MachinaException e = Assert.ThrowsAny<MachinaException>(() => bot.Connect());

        Assert.IsType<RobotConnectionException>(e);
        Assert.StartsWith("Connect() with no arguments connects to 127.0.0.1, port 7000 (a virtual controller on this computer); "
            + "for another controller call Connect(address, port). Could not connect to 127.0.0.1:7000", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ActionFailed_EmptyControllerCode_IsNotShownAsAnEmptyCode()
    {
        var failure = new ActionFailedException(new ActionWait(10), "Runtime error: line 12: movel: the target pose is out of reach", "");

        Assert.Null(failure.ControllerCode);
        Assert.DoesNotContain("(code", failure.Message, StringComparison.Ordinal);
        Assert.Contains("(code 50050)", new ActionFailedException(new ActionWait(10), "Position outside reach", "50050").Message, StringComparison.Ordinal);
    }
}
