namespace Machina.Tests.Cli;

/// <summary>A refusal reaches a tool as a structured log entry (the refused action), not only as text to filter.</summary>
public sealed class RefusalLogTests
{
    [Fact]
    public void RefusedAction_IsLoggedWithTheAction_OtherWarningsWithout()
    {
        Robot bot = Robot.Create("Alpha", RobotType.ABB);
        var entries = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => entries.Add(e);
        bot.Logger.Warning("just a warning");

        ActionRefusedException refused = Assert.Throws<ActionRefusedException>(() => bot.PopSettings());

        Assert.Equal(2, entries.Count);
        Assert.Null(entries[0].Refused);
        Assert.Same(refused.Action, entries[1].Refused);
        Assert.Equal("Refused PopSettings(); there are no saved settings to restore; every PopSettings needs an earlier PushSettings.", entries[1].Message);
        // The action is not part of the entry's value: equal to the same text without it.
        Assert.Equal(new LogEntry("Alpha", LogLevel.WARNING, entries[1].Message), entries[1]);
    }
}
