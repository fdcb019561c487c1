namespace Machina.Tests.Control;

/// <summary>
/// Reports that arrive while the link is set up are kept, and user code (log sinks included) runs only on the robot's event
/// loop, never on a driver's thread under the session's locks.
/// </summary>
public class SessionReportTests
{
    [Fact]
    public void Connect_LivePoseReportedBeforeTheLinkIsCurrent_RaisedOnceItIs()
    {
        var pose = new Vector(310, 5, 495);
        var driver = new FakeDriver
        {
            DuringConnect = l =>
            {
                l.OnMotion(new MotionSample(new Vector(1, 2, 3), Rotation.FlippedAroundY, new Joints(1, 0, 0, 0, 90, 0), null));
                l.OnMotion(new MotionSample(pose, Rotation.FlippedAroundY, new Joints(2, 0, 0, 0, 90, 0), null));
            },
        };
        var bot = OnlineRobot.Create(driver, connect: false);
        var updates = new List<Vector?>();
        bot.MotionUpdate += (_, e) => updates.Add(e.Position);

        bot.Connect("127.0.0.1", 7000);
        OnlineRobot.Flush(bot);

        Assert.Equal([pose], updates);   // the latest one, once
        Assert.Equal(pose, bot.GetMotionState()?.Position);
        Assert.Equal(new Joints(2, 0, 0, 0, 90, 0), bot.GetMotionState()?.Axes);
    }

    [Fact]
    public void Log_SessionMessages_WrittenOnTheEventLoopNotOnTheDriversThread_AHandlerMayIssue()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        int reporter = Environment.CurrentManagedThreadId;
        var seen = new List<(string Message, bool OnReporter)>();
        using var sink = bot.Logger.AddSink(e =>
        {
            lock (seen)
            {
                seen.Add((e.Message, Environment.CurrentManagedThreadId == reporter));
            }
            bot.Wait(5);   // issuing from a log sink takes the robot's issue lock: never in the wrong order
        }, LogLevel.ERROR);

        driver.Listener!.OnStopped(new RobotStoppedException("Protective stop."));
        OnlineRobot.Flush(bot);

        var (message, onReporter) = Assert.Single(seen);
        Assert.Equal("\"Online\" stopped: Protective stop. Nothing more is sent until it runs again (Resume, or at the pendant).", message);
        Assert.False(onReporter);
        Assert.Equal([1], bot.GetPendingActions().Select(a => a.Id));
    }
}
