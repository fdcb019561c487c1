using System.Diagnostics;
using Machina.Simulation;
using Machina.Tests.Support;
using Xunit.Abstractions;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// The soak's stall schedules (issue 28), per brand: a long random program streamed through a <see cref="FaultProxy"/> that,
/// at seeded points, holds the host's requests in the network, cuts the host's link and delivers what it held to the old
/// connection before or while the host connects again; on UR it also holds a driver script, which arrives after the host's
/// next attempt streams and replaces that program. Every action is executed exactly once and in order, on the controller
/// and on the host, and the robot ends where the program leaves it.
/// </summary>
public class HeldSoakTests(ITestOutputHelper output)
{
    private const int Actions = 20_000;
    private const int Events = 8;
    private static readonly TimeSpan WaitLimit = TimeSpan.FromSeconds(120);

    /// <summary>How many of the actions issued so far may still wait or run when the next hold begins.</summary>
    private const int InFlightAtHold = 100;

    [Theory]
    [InlineData("ABB", 14211)]
    [InlineData("UR", 14212)]
    [InlineData("KUKA", 14213)]
    public async Task Soak_HeldInstructionsAndScripts_EachExecutedOnceInOrder(string brand, int seed)
    {
        var watch = Stopwatch.StartNew();
        var random = new Random(seed);
        bool ur = brand == "UR";
        // ABB, KUKA: the driver connection passes the proxy. UR: the driver program's call back passes `back`, the script port `front`.
        await using FaultProxy? back = ur ? FaultProxy.Start([1], new FaultProxyOptions { Seed = seed, Holdable = true, HoldTowardsConnector = true }) : null;
        await using FaultRig rig = ur ? await FaultRig.StartUrThroughAsync(back!, logCapacity: Actions) : await FaultRig.StartAsync(brand, new VirtualFaults(), logCapacity: Actions);
        await using FaultProxy front = FaultProxy.Start(rig.ProxiedPorts, new FaultProxyOptions { Seed = seed, Holdable = true });
        FaultProxy requests = back ?? front;
        var w = rig.CreateRobot(b => { b.BlockSize = 50; b.PendingCount = 40; }, port: front.Port);
        await rig.RecoverAsync(w);
        // The program is issued in Events + 1 parts, each part after the hold that precedes it has begun: a host that streams
        // faster than the schedule advances can never run out of requests to hold (it once ran the whole program between two
        // events and the next hold waited for requests that never came).
        int part = Actions / (Events + 1), issued = 0;
        Vector IssuePart(int count)
        {
            issued += count;
            return RandomProgram.Issue(w.Bot, random, count, RandomProgram.ReachableLow, RandomProgram.ReachableHigh, jumps: true);
        }
        Vector end = IssuePart(part);
        int heldInstructions = 0, releasedDuring = 0, heldScripts = 0, recoveries = 0;
        bool scriptHeld = false;

        string step = "start";
        try
        {
        for (int k = 1; k <= Events; k++)
        {
            step = $"event {k}: advancing";
            // The last actions issued may still run while the next hold begins: the controller is busy when requests are held.
            await AdvanceAsync(rig, w, issued - InFlightAtHold);
            step = $"event {k}: holding";
            if (scriptHeld)
            {
                // The script held at the last event arrives now, after the attempt that followed it streams: its program replaces
                // the host's, and the host connects again.
                int before = w.Faults.Count;
                step = $"event {k}: a late script";
                await front.ReleaseHeldAsync().WaitAsync(Limit);
                scriptHeld = false;
                await Eventually.TrueAsync(() => w.Faults.Count > before, "the host to lose the program the late script replaced", WaitLimit);
                await rig.RecoverAsync(w);
            }
            requests.HoldNow();
            end = IssuePart(part);
            await Eventually.TrueAsync(() => requests.HeldBytes > 0, "requests to be held", WaitLimit);
            int lost = w.Faults.Count;
            step = $"event {k}: cutting";
            requests.CutHeldSenders();
            await Eventually.TrueAsync(() => w.Faults.Count > lost, "the host to see its link cut", WaitLimit);
            heldInstructions++;
            step = $"event {k}: recovering";
            if (ur && random.Next(2) == 0)
            {
                // The next script is held too: that attempt times out and the one after it streams.
                front.HoldNext();
                scriptHeld = true;
                heldScripts++;
                await requests.ReleaseHeldAsync().WaitAsync(Limit);
                w.Bot.ConnectTimeout = TimeSpan.FromSeconds(5);
                await rig.RecoverAsync(w);
                w.Bot.ConnectTimeout = Limit;
            }
            else if (random.Next(2) == 0)
            {
                await requests.ReleaseHeldAsync().WaitAsync(Limit);
                await rig.RecoverAsync(w);
            }
            else
            {
                int attempts = NextAttemptCount(rig, front);
                Task reconnect = rig.RecoverAsync(w);
                await Eventually.TrueAsync(() => NextAttemptCount(rig, front) > attempts || reconnect.IsCompleted, "the host's next attempt", WaitLimit);
                await requests.ReleaseHeldAsync().WaitAsync(Limit);
                await reconnect.WaitAsync(WaitLimit);
                releasedDuring++;
            }
        }
        if (scriptHeld)
        {
            await front.ReleaseHeldAsync().WaitAsync(Limit);
        }
        end = IssuePart(Actions - issued);
        step = "completing";
        recoveries = await rig.RunToCompletionAsync(w, WaitLimit, maxRecoveries: 100);
        }
        catch (Exception e) when (e is TimeoutException or MachinaException or Xunit.Sdk.XunitException)
        {
            IReadOnlyList<string> pendant = rig.Controller switch
            {
                VirtualUrController c => c.PendantMessages,
                VirtualAbbController c => c.PendantMessages,
                VirtualKukaController c => c.PendantMessages,
                _ => [],
            };
            Assert.Fail($"{step}: {e.GetType().Name}: {e.Message}\nhost executed {w.Executed.Count}, controller {rig.ExecutedIds.Count}, state {w.Bot.ConnectionState}, "
                + $"pending {w.Bot.GetPendingActions().Count}\nfaults: {string.Join(" | ", w.Faults.TakeLast(5).Select(f => f.Message))}"
                + $"\nretried: {string.Join(" | ", w.RecoveryErrors.TakeLast(5).Select(f => f.Message))}\npendant: {string.Join(" | ", pendant.TakeLast(12))}");
        }
        watch.Stop();

        Assert.True(w.Executed.SequenceEqual(Enumerable.Range(1, Actions)), "The host saw actions executed out of order, twice or not at all.");
        IReadOnlyList<int> log = rig.ExecutedIds;
        Assert.Equal(Actions, log.Count);
        Assert.True(log.SequenceEqual(Enumerable.Range(1, Actions)), $"The controller executed out of order or twice: first difference at {FirstDifference(log)}.");
        Assert.True(rig.Position.IsSimilar(end, 1e-6), $"{brand} ended at {rig.Position}, expected {end}");
        Assert.Empty(rig.Errors);
        Assert.Equal(Events, heldInstructions);
        output.WriteLine($"{brand}: {Actions} actions, {heldInstructions} held instruction streams ({releasedDuring} released while reconnecting), "
            + $"{heldScripts} held scripts, {recoveries} late recoveries, {w.RecoveryErrors.Count} retried attempts, {watch.Elapsed.TotalSeconds:F2} s");
        await w.Bot.DisconnectAsync();
    }
    /// <summary>Waits until the host saw <paramref name="executed"/> actions executed, connecting again whenever the link is lost.</summary>
    private static async Task AdvanceAsync(FaultRig rig, FaultRig.Watched w, int executed)
    {
        long start = Stopwatch.GetTimestamp();
        // The controller's count: the host's events may lag behind it, and the host streams at most a window ahead of it.
        while (rig.ExecutedIds.Count < executed)
        {
            Assert.True(Stopwatch.GetElapsedTime(start) < WaitLimit, $"only {rig.ExecutedIds.Count} of {executed} actions executed within {WaitLimit}");
            if (w.Bot.ConnectionState is ConnectionState.Disconnected or ConnectionState.Stopped)
            {
                await rig.RecoverAsync(w);
            }
            await Task.Delay(20);
        }
    }

    private static int FirstDifference(IReadOnlyList<int> log)
    {
        int i = 0;
        while (i < log.Count && log[i] == i + 1)
        {
            i++;
        }
        return i;
    }

    /// <summary>How many attempts reached the controller: driver connections at the proxy, or UR scripts received.</summary>
    private static int NextAttemptCount(FaultRig rig, FaultProxy front) =>
        rig.Controller is VirtualUrController ur ? ur.ScriptsReceived : front.AcceptedOn(0);


}
