namespace Machina.Tests.Core;

/// <summary>The per-robot logger (spec §18): levels, state reports for relative actions, writers and failing subscribers.</summary>
public class RobotLoggingTests
{
    [Fact]
    public void Verbose_RelativeActions_ReportTheNewState()
    {
        var bot = Robot.Create("HelloRobot", "ABB");
        bot.Logger.Level = LogLevel.VERBOSE;
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);

        bot.MoveTo(400, 300, 500);
        bot.Move(0, 0, 250);
        bot.Rotate(0, 0, 1, 90);
        bot.Speed(30);

        Assert.Equal(
            [
                "HelloRobot VERBOSE: TCP position at [400, 300, 750]",
                "HelloRobot VERBOSE: TCP orientation at [[0, -1, 0], [-1, 0, 0], [0, 0, -1]]",
                "HelloRobot VERBOSE: Settings: speed 50 mm/s, acceleration 30 mm/s², precision 5 mm, linear motion, world frame",
            ],
            log.Select(e => e.ToString()));
    }

    [Fact]
    public void Info_Default_HidesVerboseButShowsWarnings()
    {
        var bot = Robot.Create("Quiet", "ABB");
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);
        bot.MoveTo(1, 2, 3);
        bot.Move(1, 0, 0);

        Assert.Throws<ActionRefusedException>(() => bot.PopSettings());

        Assert.Equal(LogLevel.INFO, bot.Logger.Level);
        LogEntry entry = Assert.Single(log);
        Assert.Equal(LogLevel.WARNING, entry.Level);
    }

    [Fact]
    public void Writer_ReceivesFormattedLines()
    {
        var bot = Robot.Create("Writer", "ABB");
        var writer = new StringWriter { NewLine = "\n" };
        bot.Logger.Writer = writer;
        bot.Logger.Level = LogLevel.DEBUG;

        bot.Logger.Info("hello");
        bot.Logger.Debug("details");
        bot.Logger.Level = LogLevel.NONE;
        bot.Logger.Error("hidden");

        Assert.Equal("Writer INFO: hello\nWriter DEBUG: details\n", writer.ToString());
    }

    [Fact]
    public void Logged_ThrowingSubscriber_DoesNotStopTheRobot()
    {
        var bot = Robot.Create("Sturdy", "ABB");
        bot.Logger.Logged += (_, _) => throw new InvalidOperationException("bad subscriber");
        bot.MoveTo(0, 0, 0);

        Assert.Throws<ActionRefusedException>(() => bot.PopSettings());
        Assert.True(bot.Move(1, 0, 0));
        Assert.Equal(new Point(1, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void AddSink_TwoRobots_EachSinkReceivesExactlyItsRobotsEntriesAtItsLevel()
    {
        var alpha = Robot.Create("Alpha", "ABB");
        var beta = Robot.Create("Beta", "ABB");
        var alphaLog = new List<LogEntry>();
        var betaLog = new List<LogEntry>();
        alpha.Logger.AddSink(alphaLog.Add, LogLevel.WARNING);
        beta.Logger.AddSink(betaLog.Add, LogLevel.VERBOSE);

        foreach (Robot bot in new[] { alpha, beta })
        {
            bot.MoveTo(400, 300, 500);
            bot.Move(0, 0, 250);
            bot.Logger.Info("info text");
            Assert.Throws<ActionRefusedException>(() => bot.PopSettings());
        }

        const string refusal = "Refused PopSettings(); there are no saved settings to restore; every PopSettings needs an earlier PushSettings.";
        Assert.Equal([new LogEntry("Alpha", LogLevel.WARNING, refusal)], alphaLog);
        Assert.Equal(
            [
                new LogEntry("Beta", LogLevel.VERBOSE, "TCP position at [400, 300, 750]"),
                new LogEntry("Beta", LogLevel.INFO, "info text"),
                new LogEntry("Beta", LogLevel.WARNING, refusal),
            ],
            betaLog);
    }

    [Fact]
    public void AddSink_LevelIndependentOfLoggerLevel_AndDisposeStops()
    {
        var bot = Robot.Create("Host", "ABB");
        bot.Logger.Level = LogLevel.ERROR;
        var events = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => events.Add(e);
        var writer = new StringWriter { NewLine = "\n" };
        var sinkLog = new List<LogEntry>();

        IDisposable toWriter = bot.Logger.AddSink(writer, LogLevel.DEBUG);
        using (bot.Logger.AddSink(sinkLog.Add, LogLevel.INFO))
        {
            Assert.True(bot.Logger.IsEnabled(LogLevel.DEBUG));
            bot.Logger.Debug("details");
            bot.Logger.Info("hello");
            bot.Logger.Error("broken");
        }
        toWriter.Dispose();
        bot.Logger.Error("after");

        Assert.Equal("Host DEBUG: details\nHost INFO: hello\nHost ERROR: broken\n", writer.ToString());
        Assert.Equal([new LogEntry("Host", LogLevel.INFO, "hello"), new LogEntry("Host", LogLevel.ERROR, "broken")], sinkLog);
        Assert.Equal([new LogEntry("Host", LogLevel.ERROR, "broken"), new LogEntry("Host", LogLevel.ERROR, "after")], events);
        Assert.False(bot.Logger.IsEnabled(LogLevel.WARNING));
    }

    [Fact]
    public void AddSink_ThrowingSink_OtherSinksStillReceive()
    {
        var bot = Robot.Create("Sturdy", "ABB");
        var log = new List<LogEntry>();
        bot.Logger.AddSink(_ => throw new InvalidOperationException("bad sink"));
        bot.Logger.AddSink(log.Add);

        bot.Logger.Warning("careful");

        Assert.Equal([new LogEntry("Sturdy", LogLevel.WARNING, "careful")], log);
        Assert.Throws<ArgumentNullException>(() => bot.Logger.AddSink((Action<LogEntry>)null!));
        Assert.Throws<ArgumentOutOfRangeException>(() => bot.Logger.AddSink(log.Add, (LogLevel)9));
    }
}
