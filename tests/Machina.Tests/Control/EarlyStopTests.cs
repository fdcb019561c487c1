namespace Machina.Tests.Control;

/// <summary>
/// A controller that reports a stop while the connection is still being set up (UR: RTDE shows the protective stop right after
/// the driver program's handshake, before the session made the link current): the stop must not be lost.
/// </summary>
public class EarlyStopTests
{
    [Fact]
    public void Connect_StopReportedBeforeTheLinkIsCurrent_StoppedOnceConnectedAndNothingSent()
    {
        var driver = new FakeDriver { DuringConnect = l => l.OnStopped(new RobotStoppedException("Protective stop while connecting.")) };
        var bot = OnlineRobot.Create(driver, connect: false);
        var stops = new List<(bool Stopped, string? Reason)>();
        bot.ControllerStopped += (_, e) => stops.Add((e.IsStopped, e.Reason?.Message));

        bot.Connect("127.0.0.1", 7000);
        bot.MoveTo(400, 0, 400);
        OnlineRobot.Flush(bot);

        Assert.Equal(ConnectionState.Stopped, bot.ConnectionState);
        Assert.Equal([(true, "Protective stop while connecting.")], stops);
        Assert.Empty(driver.Sent);

        driver.Listener!.OnResumed();
        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        Assert.Equal([1], driver.Sent.Select(a => a.Id));
        bot.Disconnect();
    }

    [Fact]
    public void Connect_StopAndResumeBothBeforeTheLinkIsCurrent_ConnectedAndSending()
    {
        var driver = new FakeDriver
        {
            DuringConnect = l =>
            {
                l.OnStopped(new RobotStoppedException("Protective stop while connecting."));
                l.OnResumed();
            },
        };
        var bot = OnlineRobot.Create(driver, connect: false);

        bot.Connect("127.0.0.1", 7000);
        bot.MoveTo(400, 0, 400);

        Assert.Equal(ConnectionState.Connected, bot.ConnectionState);
        Assert.Equal([1], driver.Sent.Select(a => a.Id));
        bot.Disconnect();
    }
}
