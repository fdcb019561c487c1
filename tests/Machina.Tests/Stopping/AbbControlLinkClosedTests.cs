using Machina.Tests.Online;

namespace Machina.Tests.Stopping;

/// <summary>
/// A command to the ABB monitor task (here Pause) when the controller closes its links before it answered: the host closes the
/// driver, no answer can come any more, so the call fails at once, saying the link closed. Before session 36 it waited out the command's 10 s limit and then said the monitor
/// "did not answer" (a <see cref="RobotStoppedException"/>), as if the controller were slow.
/// </summary>
public class AbbControlLinkClosedTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task Pause_MonitorLinkClosesBeforeTheAnswer_FailsWithTheClosedLink()
    {
        await using var controller = ScriptedAbbController.Start();
        Task<Robot> connecting = OnlineTestSupport.ConnectRobotAsync("HelloRobot", "ABB", controller.Port, null);
        await controller.AcceptAsync();
        Robot bot = await connecting.WaitAsync(Long);
        try
        {
            Task pausing = bot.PauseAsync();
            await controller.CloseOnAsync("P"); // the controller goes away: the host closes its links

            var e = await Assert.ThrowsAsync<RobotConnectionException>(() => pausing.WaitAsync(Long));
            Assert.Equal("The link to the ABB monitor task was closed before it answered the command.", e.Message);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}
