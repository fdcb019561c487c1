namespace Machina.Tests.Docs;

/// <summary>docs/migrating.md covers what a port of the original meets first, and ConnectionManager("machina") says it in the log.</summary>
public sealed class MigratingFirstErrorsTests
{
    [Fact]
    public void ConnectionManagerMachina_OnAKuka_ReturnsFalse_AndWarnsThatTheDriverIsLoadedByHand()
    {
        var bot = Robot.Create("Port", "KUKA");
        var log = new List<LogEntry>();
        bot.Logger.Logged += (_, e) => log.Add(e);

        bool accepted = bot.ConnectionManager("machina");

        Assert.False(accepted);
        LogEntry warning = Assert.Single(log);
        Assert.Equal(LogLevel.WARNING, warning.Level);
        Assert.Equal(
            "ConnectionManager(\"machina\") is available on ABB controllers only, so nothing changed: Machina does not load or start the driver " +
            "on a KUKA controller (load and start it by hand; its files come from \"machina drivers\" or GetDeviceDriverModules, then Connect); " +
            "on a UR there is nothing to load, Connect sends the driver script itself. " +
            "See docs/migrating.md#the-driver-is-loaded-by-hand.",
            warning.Message);
        Assert.True(bot.ConnectionManager("user"));
        Assert.Single(log);
    }

    [Fact]
    public void Migrating_HasTheSectionTheWarningLinksTo()
    {
        List<string> lines = DocText.ReadLines("docs/migrating.md");
        Assert.Contains("### The driver is loaded by hand", lines);
        string anchor = Robot.MachinaManagerRefused[(Robot.MachinaManagerRefused.IndexOf('#') + 1)..].TrimEnd('.');
        Assert.Equal("the-driver-is-loaded-by-hand", anchor);
    }

    [Theory]
    [InlineData("`using Machina.Types.Geometry;`", "CS0234")]
    [InlineData("**`ActionCompleted` and `RemainingActions`**", "PendingExecutionTotal")]
    [InlineData("**`Compile()` on an online robot**", "Compile works in offline mode; this robot is streaming its actions to a controller.")]
    [InlineData("**`ConnectionManager(\"machina\")`**", "Robot Web Services")]
    public void Migrating_FirstErrors_SaysWhatToWriteInstead(string topic, string answer)
    {
        string text = string.Join(" ", DocText.ReadLines("docs/migrating.md").Select(l => l.Trim()));
        int start = text.IndexOf("## The first errors a port meets", StringComparison.Ordinal);
        int end = text.IndexOf("## Where the same code would give different numbers", StringComparison.Ordinal);
        Assert.True(start >= 0 && end > start, "docs/migrating.md has no section \"The first errors a port meets\".");
        string section = text[start..end];
        int at = section.IndexOf(topic, StringComparison.Ordinal);
        Assert.True(at >= 0, $"The section does not cover {topic}.");
        int next = section.IndexOf("* **", at + 1, StringComparison.Ordinal);
        string item = section[at..(next < 0 ? section.Length : next)];
        Assert.Contains(answer, item, StringComparison.Ordinal);
    }
}
