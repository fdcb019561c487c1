using Machina.Cli.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

/// <summary>
/// <c>machina sim</c>'s activity sleeps while its controller is idle (no timer pending on its clock: an idle twin wakes no thread)
/// and looks when the controller says something changed: a pendant text or an output is told without any tick of its clock.
/// </summary>
public sealed class ControllerActivityWakeTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task IdleController_ActivityHoldsNoTimer_AChangeIsToldWithoutATick()
    {
        await using RunningController controller = await VirtualControllers.StartAsync(RobotType.UR, new VirtualControllerOptions(SpeedFactor: 1000), CancellationToken.None);
        var twin = ((Machina.Simulation.VirtualUrController)controller.Inner.Controller).Twin;
        var clock = new ManualClock();
        var lines = new List<string>();
        void Log(string line)
        {
            lock (lines)
            {
                lines.Add(line);
            }
        }
        bool Told(string line)
        {
            lock (lines)
            {
                return lines.Contains(line);
            }
        }
        var changes = controller.Inner.Changes;
        bool Asleep() => changes.IsAwaited && clock.PendingTimers == 0;
        await using (ControllerActivity activity = ControllerActivity.Start(controller, Log, clock))
        {
            // It looks at once, then waits a period before it may look again (its one timer); once that passed, it sleeps on the
            // controller's signal with no timer pending, and moving the clock makes it look at nothing.
            await Eventually.TrueAsync(() => { AdvanceIfPending(clock); return Asleep(); }, "the idle activity to sleep without a timer", Bound);
            clock.Advance(TimeSpan.FromSeconds(10));
            Assert.True(Asleep());

            // A change wakes it: told with the clock standing still (no tick of it).
            twin.Receive("def tell():\n  textmsg(\"woken\")\nend\n");
            Assert.True(twin.WaitForEnd(Bound));
            await Eventually.TrueAsync(() => Told("  pendant: woken"), "the pendant text told without a tick", Bound);

            // An output written by the twin's program wakes it as well (its signals tell the controller's signal; else it would sleep on).
            await Eventually.TrueAsync(() => { AdvanceIfPending(clock); return Asleep(); }, "the activity to sleep again", Bound);
            twin.Receive("def output():\n  set_standard_digital_out(3, True)\nend\n");
            Assert.True(twin.WaitForEnd(Bound));
            await Eventually.TrueAsync(() => { AdvanceIfPending(clock); return Told("  output    digital 3 on"); }, "the output told", Bound);
        }
    }

    /// <summary>Ends the activity's period after a look, if it waits one.</summary>
    private static void AdvanceIfPending(ManualClock clock)
    {
        if (clock.PendingTimers > 0)
        {
            clock.Advance(ControllerActivity.Period);
        }
    }
}
