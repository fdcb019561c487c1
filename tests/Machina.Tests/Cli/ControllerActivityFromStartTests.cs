using Machina.Cli.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

/// <summary>
/// <c>machina sim</c> starts its activity just after the controller: what the controller's program wrote to the pendant before
/// the activity's first look (the ABB driver's version line) is told too, not skipped (it once raced the first look).
/// </summary>
public sealed class ControllerActivityFromStartTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task PendantWrittenBeforeTheFirstLook_IsTold()
    {
        await using RunningController controller = await VirtualControllers.StartAsync(RobotType.ABB, new VirtualControllerOptions(SpeedFactor: 1000), CancellationToken.None);
        using (var written = new CancellationTokenSource(Bound))
        {
            while (!controller.Inner.PendantMessages.Any(m => m.StartsWith("Machina driver 1.", StringComparison.Ordinal)))
            {
                await Task.Delay(5, written.Token);
            }
        }
        var lines = new List<string>();
        await using (ControllerActivity activity = ControllerActivity.Start(controller, line => { lock (lines) { lines.Add(line); } }, new ManualClock()))
        {
            activity.Flush();
        }
        string version = controller.Inner.PendantMessages.First(m => m.StartsWith("Machina driver 1.", StringComparison.Ordinal));
        lock (lines)
        {
            Assert.Equal(1, lines.Count(l => l == "  pendant: " + version));
        }
    }
}
