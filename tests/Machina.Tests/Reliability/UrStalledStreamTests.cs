using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// A link that stalls in the middle of an instruction (its header arrived, its values are held by a slow network) makes the
/// UR driver program give up on its stream: it halts without a runtime error, the instruction received and not executed,
/// exactly as a program that failed the instruction would look, had it not said so. It first publishes its instance number
/// negated on RTDE, and the host reports a lost link naming the stall, never a failed action; connecting again runs the
/// rest once (docs/protocol-ur.md §5).
/// </summary>
public class UrStalledStreamTests
{
    private const int Actions = 40;

    /// <summary>The first six moves (32 bytes each: id, code, six values) and the seventh's id, code and first value pass.</summary>
    private const int PassedBytes = 6 * 32 + 12;

    [Fact]
    public async Task ValuesHeldMidInstruction_DriverGivesUp_HostReportsALostLinkNamingTheStall_NoActionFails()
    {
        await using var back = FaultProxy.Start([1], new FaultProxyOptions { Seed = 14313, HoldConnections = 1, HoldAfterBytes = PassedBytes, HoldTowardsConnector = true });
        await using var rig = await FaultRig.StartUrThroughAsync(back);
        var controller = (VirtualUrController)rig.Controller;
        var failed = new ConcurrentQueue<ActionFailedArgs>();
        int connections = 0;
        var w = rig.CreateRobot(bot =>
        {
            // The first connection's driver waits 1 s for an instruction's values (the next ones 5 s, as on a robot); the hold
            // never ends before it. The session takes its driver factory when the robot goes online.
            bot.ControlMode("offline");
            bot.DriverFactory = () => new UrDriver(new DeviceContext(new RobotLogger("stall"), TimeProvider.System, "FaultBot", null, 50))
            {
                ValuesTimeout = Interlocked.Increment(ref connections) == 1 ? TimeSpan.FromSeconds(1) : UrDriverScript.DefaultValuesTimeout,
            };
            bot.ControlMode("online");
            bot.ActionFailed += (_, e) => failed.Enqueue(e);
        });
        await w.Bot.ConnectAsync("127.0.0.1", rig.Port).WaitAsync(Limit);
        FaultMatrixTests.IssueProgram(w.Bot, Actions);

        await EventuallyAsync(() => !w.Faults.IsEmpty || !failed.IsEmpty, "the host to hear that the driver program stopped");
        await w.Bot.FlushEventsAsync().WaitAsync(Limit);
        Assert.True(failed.IsEmpty, "an action was reported failed: " + string.Join(" | ", failed.Select(f => $"{f.Action.Id}: {f.Failure.Message}")));
        MachinaException fault = Assert.Single(w.Faults);
        Assert.IsType<RobotConnectionException>(fault);
        Assert.True(fault.Message.Contains("instruction stream broke", StringComparison.Ordinal), fault.Message);
        Assert.True(fault.Message.Contains("did not arrive whole within 1 s (a stalled link)", StringComparison.Ordinal), fault.Message);
        Assert.Equal(ConnectionState.Disconnected, w.Bot.ConnectionState);
        Assert.True(back.HeldBytes > 0, "the seventh move's values are still held");
        Assert.Equal(Enumerable.Range(1, 6), rig.ExecutedIds);
        Assert.Contains(controller.PendantMessages, l => l.Contains("Machina: incomplete instruction, stopping. Expected values: 6", StringComparison.Ordinal));
        Assert.True(controller.InstanceRegister < 0, $"output_int_register_26 is {controller.InstanceRegister}");
        Assert.False(controller.IsProgramRunning);

        // Connecting again (the usual 5 s driver) resumes from the registers: the seventh move and the rest run once each.
        await rig.RecoverAsync(w);
        await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 0);
        FaultMatrixTests.AssertRanOnce(rig, w, Actions);
        Assert.True(failed.IsEmpty);
        Assert.Single(w.Faults);
        Assert.Equal(2, connections);
        await w.Bot.DisconnectAsync();
    }
}
