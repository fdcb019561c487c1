using System.Collections.Concurrent;
using Machina.Simulation;

namespace Machina.Tests.Reliability;

/// <summary>
/// A program reset on the KUKA (the fault plan's RestartLosingBuffer) empties the driver's ring but keeps its progress, a
/// data-list variable: the host that reconnects learns which actions ran, even when their acknowledgements were lost with the
/// connection, and sends again only what the ring lost. Before, the driver reported a fresh state after a reset and the host
/// sent again every action it had not seen acknowledged: about one run in six executed some actions twice.
/// </summary>
public class KukaProgramResetTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);

    [Fact]
    public async Task Reset_ReportsTheLastExecutedAction_AndTheHostResumesWhereTheControllerIs()
    {
        var faults = new VirtualFaults { After = 12, Kinds = [VirtualFault.RestartLosingBuffer] };
        await using var rig = await FaultRig.StartAsync("KUKA", faults);
        var w = rig.CreateRobot(b => { b.BlockSize = 20; b.PendingCount = 10; });
        var log = new ConcurrentQueue<string>();
        using var sink = w.Bot.Logger.AddSink(e => log.Enqueue(e.Message), LogLevel.INFO);
        // All 40 issued before the connection: the first block of 20 is in flight when the 12th acknowledgement brings the reset
        // (issued while streaming, a slow test thread could let the controller run and acknowledge all it had, leaving nothing to resume).
        for (int i = 0; i < 40; i++)
        {
            w.Bot.MoveTo(500 + i, 0, 600);
        }
        await rig.RecoverAsync(w);

        int recoveries = await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 5);

        Assert.Equal(1, recoveries);
        Assert.Equal(Enumerable.Range(1, 40), rig.ExecutedIds);
        Assert.Equal(Enumerable.Range(1, 40), w.Executed);
        Assert.Contains(log, m => m.StartsWith("Resumed where the controller is: ", StringComparison.Ordinal));
        Assert.DoesNotContain(log, m => m.StartsWith("The controller does not know", StringComparison.Ordinal));
        Assert.Contains("program reset: machina_kuka_driver starts again from the top", rig.PendantMessages);
        Assert.True(rig.Position.IsSimilar(new Vector(539, 0, 600), 1e-6), $"ended at {rig.Position}");
        await w.Bot.DisconnectAsync();
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(4)]
    [InlineData(5)]
    [InlineData(6)]
    public async Task FrequentResets_EachActionExecutedOnceInOrder(int seed)
    {
        const int Actions = 6000;
        var faults = new VirtualFaults
        {
            Seed = seed, Chance = 1.0 / 150, Delay = TimeSpan.FromMilliseconds(1),
            Kinds = [VirtualFault.RestartLosingBuffer, VirtualFault.Drop, VirtualFault.Truncate, VirtualFault.RestartKeepingBuffer],
        };
        await using var rig = await FaultRig.StartAsync("KUKA", faults, logCapacity: 2 * Actions);
        var w = rig.CreateRobot(b => { b.BlockSize = 50; b.PendingCount = 40; });
        await rig.RecoverAsync(w);
        Vector end = RandomProgram.Issue(w.Bot, new Random(seed), Actions, new Vector(400, -100, 400), new Vector(600, 100, 600), jumps: true);

        await rig.RunToCompletionAsync(w, Limit, maxRecoveries: 1000);

        IReadOnlyList<int> executed = rig.ExecutedIds;
        int first = Enumerable.Range(0, Math.Min(executed.Count, Actions)).FirstOrDefault(i => executed[i] != i + 1, -1);
        Assert.True(first < 0 && executed.Count == Actions,
            $"{executed.Count} executions, first out of order at {first}: {string.Join(",", executed.Skip(Math.Max(0, first - 3)).Take(10))}");
        Assert.True(w.Executed.SequenceEqual(Enumerable.Range(1, Actions)), "The host saw actions executed out of order, twice or not at all.");
        Assert.True(rig.Position.IsSimilar(end, 1e-6), $"ended at {rig.Position}, expected {end}");
        Assert.Contains(VirtualFault.RestartLosingBuffer, rig.InjectedFaults);
        await w.Bot.DisconnectAsync();
    }
}
