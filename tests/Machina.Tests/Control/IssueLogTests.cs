namespace Machina.Tests.Control;

/// <summary>
/// Log lines written while the robot's issue lock is held (refusals, the cursor's warnings) reach the log sinks only once
/// the lock is released: a sink may issue from another thread, or ask the online session, without a deadlock.
/// </summary>
public class IssueLogTests
{
    /// <summary>From a sink: issues a Wait on another thread and says whether it got through within 5 s (it cannot while the issue lock is held).</summary>
    private static bool OtherThreadCanIssue(Robot bot) => Task.Run(() => bot.Wait(5)).Wait(TimeSpan.FromSeconds(5));

    [Fact]
    public void Refusal_Offline_SinkRunsAfterTheIssueLockIsReleased()
    {
        var bot = Robot.Create("Host", "ABB");
        var seen = new List<(string Message, bool OtherCouldIssue)>();
        using var sink = bot.Logger.AddSink(e => seen.Add((e.Message, OtherThreadCanIssue(bot))), LogLevel.WARNING);

        Assert.Throws<ActionRefusedException>(() => bot.PopSettings());

        var (message, otherCouldIssue) = Assert.Single(seen);
        Assert.Equal("Refused PopSettings(); there are no saved settings to restore; every PopSettings needs an earlier PushSettings.", message);
        Assert.True(otherCouldIssue);
        Assert.Equal([1], bot.GetProgramActions().Select(a => a.Id));   // the Wait the sink issued
    }

    [Fact]
    public void Refusal_Online_SinkMayAskTheSessionAndIssue()
    {
        var driver = new FakeDriver();
        var bot = OnlineRobot.Create(driver);
        var seen = new List<(int Pending, bool OtherCouldIssue)>();
        using var sink = bot.Logger.AddSink(e => seen.Add((bot.GetPendingActions().Count, OtherThreadCanIssue(bot))), LogLevel.WARNING);

        Assert.Throws<ActionRefusedException>(() => bot.PopSettings());

        var (pending, otherCouldIssue) = Assert.Single(seen);
        Assert.Equal(0, pending);
        Assert.True(otherCouldIssue);
        Assert.Equal([1], driver.Sent.Select(a => a.Id));   // the Wait the sink issued was released
    }
}
