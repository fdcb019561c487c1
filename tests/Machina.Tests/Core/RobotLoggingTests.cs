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
                "HelloRobot VERBOSE: Settings: World Linear 50-30-5 0",
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
}
