namespace Machina.Tests.Control;

/// <summary>
/// A controller that reports a stop or a live pose while the connection is still being set up (UR: RTDE shows the protective
/// stop right after the driver program's handshake; ABB and KUKA: the monitor's first report), before the session made the
/// link current: neither may be lost.
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
    [Fact]
    public void Connect_MotionReportedBeforeTheLinkIsCurrent_TheLatestIsRaisedOnceConnected()
    {
        var driver = new FakeDriver
        {
            DuringConnect = l =>
            {
                l.OnMotion(new MotionSample(new Vector(1, 2, 3), Rotation.Identity, new Joints(0, 0, 0, 0, 90, 0), null));
                l.OnMotion(new MotionSample(new Vector(4, 5, 6), Rotation.Identity, new Joints(0, 0, 0, 0, 91, 0), null));
            },
        };
        var bot = OnlineRobot.Create(driver, connect: false);
        var updates = new List<Vector?>();
        bot.MotionUpdate += (_, e) => updates.Add(e.Position);

        bot.Connect("127.0.0.1", 7000);
        OnlineRobot.Flush(bot);

        Assert.Equal([new Vector(4, 5, 6)], updates);
        bot.Disconnect();
    }
}
