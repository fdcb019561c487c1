using System.Collections.Concurrent;
using System.Diagnostics;
using Machina.Simulation;
using Xunit.Abstractions;

namespace Machina.Tests.Reliability;

/// <summary>
/// A seeded soak per brand: 100,000 actions streamed to a virtual controller that injects a random fault after about one
/// acknowledgement in 2,000 (drops, delays, garbage, truncated and unknown acknowledgements, restarts keeping or losing the
/// buffer, and on UR protective stops), recovered the user's way (Connect again, Resume). Over the whole run every action
/// is executed exactly once and in order, on the controller (its execution log) and on the host (<c>ActionExecuted</c>),
/// and the robot ends where the program leaves it. The time each brand took is written to the test output.
/// </summary>
public class SoakTests(ITestOutputHelper output)
{
    private const int Actions = 100_000;
    private const double FaultChance = 1.0 / 2000;
    private static readonly TimeSpan WaitLimit = TimeSpan.FromSeconds(60);

    private static readonly VirtualFault[] Kinds =
    [
        VirtualFault.Drop, VirtualFault.Delay, VirtualFault.Garbage, VirtualFault.Truncate, VirtualFault.UnknownAcknowledgement,
        VirtualFault.RestartKeepingBuffer, VirtualFault.RestartLosingBuffer,
    ];

    [Theory]
    [InlineData("ABB", 14201)]
    [InlineData("UR", 14202)]
    [InlineData("KUKA", 14203)]
    public async Task Soak_HundredThousandActionsWithRandomFaults_EachExecutedOnceInOrder(string brand, int seed)
    {
        var watch = Stopwatch.StartNew();
        VirtualFault[] kinds = brand == "UR" ? [.. Kinds, VirtualFault.ProtectiveStop] : Kinds;
        var faults = new VirtualFaults { Seed = seed, Chance = FaultChance, Kinds = kinds, Delay = TimeSpan.FromMilliseconds(1) };
        // Room for repeats in the controller's log, so that an action run twice shows where it happened.
        await using var rig = await FaultRig.StartAsync(brand, faults, logCapacity: 2 * Actions);
        // A wide window (at most 89 actions on the controller: within KUKA's ring of 100).
        var w = rig.CreateRobot(b => { b.BlockSize = 50; b.PendingCount = 40; });
        // The host's log (warnings and reconnections), shown with the controller's pendant when the controller's log is wrong.
        var hostLog = new ConcurrentQueue<string>();
        using var sink = w.Bot.Logger.AddSink(e => hostLog.Enqueue(e.ToString()), LogLevel.INFO);
        await rig.RecoverAsync(w);
        // The KUKA twin moves a KR 6 R900 sixx with its tool pointing down, which cannot reach the lowest points near its base
        // (MoveTo(231, -71, 323) is not reachable): its program runs 200 mm further out and 100 mm higher.
        Vector shift = brand == "KUKA" ? new Vector(200, 0, 100) : Vector.Zero;
        Vector end = RandomProgram.Issue(w.Bot, new Random(seed), Actions, new Vector(200, -100, 300) + shift, new Vector(400, 100, 500) + shift, jumps: true);

        int recoveries;
        try
        {
            recoveries = await rig.RunToCompletionAsync(w, WaitLimit, maxRecoveries: 1000);
        }
        catch (TimeoutException)
        {
            // A stalled run says where it stalled: the host's last lines, the controller's pendant and what it executed last.
            output.WriteLine($"Stalled after {rig.ExecutedIds.Count} executions (last {string.Join(",", rig.ExecutedIds.TakeLast(5))}), "
                + $"{w.Executed.Count} seen executed by the host.");
            output.WriteLine("Host log:\n  " + string.Join("\n  ", hostLog.TakeLast(400)));
            output.WriteLine("Controller pendant:\n  " + string.Join("\n  ", rig.PendantMessages.TakeLast(200)));
            throw;
        }
        watch.Stop();

        Assert.True(w.Executed.SequenceEqual(Enumerable.Range(1, Actions)), "The host saw actions executed out of order, twice or not at all.");
        IReadOnlyList<int> log = rig.ExecutedIds;
        int at = FirstDifference(log);
        if (at != Actions || log.Count != Actions)
        {
            output.WriteLine("Host log:\n  " + string.Join("\n  ", hostLog.TakeLast(400)));
            output.WriteLine("Controller pendant:\n  " + string.Join("\n  ", rig.PendantMessages));
        }
        Assert.True(at == Actions && log.Count == Actions,
            $"The controller executed out of order or twice ({log.Count} executions): first difference at {at}: {string.Join(",", log.Skip(Math.Max(0, at - 5)).Take(12))}.");
        Assert.True(rig.Position.IsSimilar(end, 1e-6), $"{brand} ended at {rig.Position}, expected {end}");
        Assert.Empty(rig.Errors);
        Assert.Empty(w.Bot.GetPendingActions());
        IReadOnlyList<VirtualFault> injected = rig.InjectedFaults;
        Assert.All(kinds, k => Assert.Contains(k, injected));
        Assert.InRange(recoveries, 1, injected.Count);
        output.WriteLine($"{brand}: {Actions} actions, {injected.Count} faults ({string.Join(", ", injected.GroupBy(f => f).Select(g => $"{g.Key} {g.Count()}"))}), "
            + $"{recoveries} recoveries, {watch.Elapsed.TotalSeconds:F2} s");
        foreach (var e in w.RecoveryErrors.GroupBy(e => e.Message.Length > 90 ? e.Message[..90] : e.Message))
        {
            output.WriteLine($"  retried {e.Count()}x: {e.Key}");
        }
        await w.Bot.DisconnectAsync();
    }
    private static int FirstDifference(IReadOnlyList<int> log)
    {
        for (int i = 0; i < log.Count && i < Actions; i++)
        {
            if (log[i] != i + 1)
            {
                return i;
            }
        }
        return Math.Min(log.Count, Actions);
    }
}
