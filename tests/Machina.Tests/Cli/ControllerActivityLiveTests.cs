using Machina.Cli.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

/// <summary>
/// <c>machina sim</c>'s activity read from a running controller through its "since" reads: what it tells does not depend on
/// how full the controller's logs are (they keep their last 1000 pendant texts and errors, 4096 requests and ids).
/// </summary>
public sealed class ControllerActivityLiveTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task Flush_PendantLogAlreadyFull_StillTellsEachNewText()
    {
        await using RunningController controller = await VirtualControllers.StartAsync(RobotType.UR, new VirtualControllerOptions(SpeedFactor: 1000), CancellationToken.None);
        var twin = ((Machina.Simulation.VirtualUrController)controller.Inner.Controller).Twin;
        var lines = new List<string>();
        await using (ControllerActivity activity = ControllerActivity.Start(controller, lines.Add, new ManualClock()))
        {
            // 1000 texts fill the pendant's log; the activity is told them.
            twin.Receive("def fill():\n  i = 0\n  while i < 1000:\n    textmsg(\"fill \", i)\n    i = i + 1\n  end\nend\n");
            Assert.True(twin.WaitForEnd(Bound));
            activity.Flush();
            Assert.Equal("  pendant: fill 999", lines.Last(l => l.StartsWith("  pendant: fill ", StringComparison.Ordinal)));

            // Three more: the log stays at 1000 (its oldest dropped), and the three are told.
            lines.Clear();
            twin.Receive("def more():\n  textmsg(\"more 1\")\n  textmsg(\"more 2\")\n  textmsg(\"more 3\")\nend\n");
            Assert.True(twin.WaitForEnd(Bound));
            activity.Flush();
        }
        Assert.Equal(["  pendant: more 1", "  pendant: more 2", "  pendant: more 3"], lines.Where(l => l.StartsWith("  pendant: more", StringComparison.Ordinal)));
        Assert.Equal(1000, controller.Inner.PendantMessages.Count);
    }
}
