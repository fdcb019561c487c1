using System.Diagnostics;
using System.Globalization;
using Machina.Simulation;
using Machina.Tests.Support;
using Xunit.Abstractions;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// A chaos run (issue 28): seeded trials per brand, each a program of <see cref="Actions"/> moves streamed through
/// <see cref="FaultProxy"/>s with one fault mode (connections closed at a seeded byte, requests held and the link cut, bytes
/// split and delayed, garbage towards the host, a held driver script on UR, or a mix), recovered the user's way. No action
/// may be lost or run twice. The suite runs one trial per mode and brand; <c>MACHINA_CHAOS_TRIALS=N</c> runs N per brand
/// (the modes in turn, seeds from <see cref="FirstSeed"/> on, or from S with <c>MACHINA_CHAOS_SEED=S</c>: a seed always takes
/// the same mode), and docs/reliability.md reports such a run with its seeds.
/// </summary>
public class ChaosTests(ITestOutputHelper output)
{
    private const int Actions = 1500;
    private const int FirstSeed = 28_000;
    private static readonly TimeSpan WaitLimit = TimeSpan.FromSeconds(120);

    /// <summary>The fault modes, in the order trials take them.</summary>
    internal enum Mode { Close, Stall, Delay, Bytes, Garbage, Held, Mixed }

    [Theory]
    [InlineData("ABB")]
    [InlineData("UR")]
    [InlineData("KUKA")]
    public async Task Chaos_SeededTrials_NothingLostNothingRunTwice(string brand)
    {
        Mode[] modes = Enum.GetValues<Mode>();
        int trials = int.TryParse(Environment.GetEnvironmentVariable("MACHINA_CHAOS_TRIALS"), NumberStyles.Integer, CultureInfo.InvariantCulture, out int n) && n > 0 ? n : modes.Length;
        int first = int.TryParse(Environment.GetEnvironmentVariable("MACHINA_CHAOS_SEED"), NumberStyles.Integer, CultureInfo.InvariantCulture, out int s) && s >= FirstSeed ? s : FirstSeed;
        var problems = new List<string>();
        var watch = Stopwatch.StartNew();
        int recoveries = 0;
        for (int t = 0; t < trials; t++)
        {
            int seed = first + t;
            Mode mode = modes[(seed - FirstSeed) % modes.Length];
            try
            {
                recoveries += await RunTrialAsync(brand, seed, mode);
            }
            catch (Exception e) when (e is TimeoutException or MachinaException or Xunit.Sdk.XunitException)
            {
                problems.Add($"seed {seed} ({mode}): {e.GetType().Name}: {e.Message}");
            }
        }
        output.WriteLine($"{brand}: {trials} trials of {Actions} actions (seeds {first}-{first + trials - 1}), {problems.Count} failed, "
            + $"{recoveries} recoveries, {watch.Elapsed.TotalSeconds:F1} s");
        Assert.True(problems.Count == 0, string.Join("\n", problems));
    }

    /// <summary>One trial: a fresh controller and proxies, the program, the mode's faults; returns the recoveries it took.</summary>
    private static async Task<int> RunTrialAsync(string brand, int seed, Mode mode)
    {
        var random = new Random(seed);
        bool ur = brand == "UR";
        bool stall = mode is Mode.Stall or Mode.Mixed;
        // UR's driver calls the host back: that link passes `back`, where requests are held; ABB's and KUKA's pass `front`.
        await using FaultProxy? back = ur ? FaultProxy.Start([1], new FaultProxyOptions { Seed = seed, Holdable = stall, HoldTowardsConnector = true }) : null;
        await using FaultRig rig = ur ? await FaultRig.StartUrThroughAsync(back!, logCapacity: Actions) : await FaultRig.StartAsync(brand, new VirtualFaults(), logCapacity: Actions);
        await using FaultProxy front = FaultProxy.Start(rig.ProxiedPorts, FrontOptions(brand, seed, mode, random));
        FaultProxy requests = back ?? front;
        var w = rig.CreateRobot(b => { b.BlockSize = 20; b.PendingCount = 10; }, port: front.Port);
        if (mode == Mode.Held)
        {
            w.Bot.ConnectTimeout = TimeSpan.FromSeconds(4); // on UR the first script is held: that attempt times out
        }
        await rig.RecoverAsync(w);
        w.Bot.ConnectTimeout = Limit;
        Vector end;
        if (stall)
        {
            // The program up to the stall point is issued first and the rest once it ran, so the rest's requests are held. (Issued
            // whole, a test thread slowed by the load could notice the point only after the whole program ran: nothing to hold.)
            int at = random.Next(Actions / 10, Actions * 8 / 10);
            RandomProgram.Issue(w.Bot, random, at, RandomProgram.ReachableLow, RandomProgram.ReachableHigh, jumps: false);
            await Eventually.TrueAsync(() => rig.ExecutedIds.Count >= at || w.Bot.ConnectionState != ConnectionState.Connected, "the stall point", WaitLimit);
            requests.HoldNow();
            end = RandomProgram.Issue(w.Bot, random, Actions - at, RandomProgram.ReachableLow, RandomProgram.ReachableHigh, jumps: false);
        }
        else
        {
            end = RandomProgram.Issue(w.Bot, random, Actions, RandomProgram.ReachableLow, RandomProgram.ReachableHigh, jumps: false);
        }

        bool heldFirst = mode == Mode.Held && !ur; // ABB, KUKA: the first connection's requests are held from a seeded byte on
        if (stall || heldFirst)
        {
            int acceptedAtHold = requests.Accepted;
            if (w.Bot.ConnectionState == ConnectionState.Connected)
            {
                await Eventually.TrueAsync(() => requests.HeldBytes > 0 || w.Bot.ConnectionState != ConnectionState.Connected, "requests to be held", WaitLimit,
                    () => $"The host is {w.Bot.ConnectionState}, the controller ran {rig.ExecutedIds.Count} and the host saw {w.Executed.Count}; "
                        + $"{requests.Accepted} request links ({acceptedAtHold} when held), {w.Faults.Count} faults: {string.Join(" | ", w.Faults.Select(f => f.Message))}");
                int lost = w.Faults.Count;
                requests.CutHeldSenders();
                await Eventually.TrueAsync(() => w.Faults.Count > lost || w.Bot.ConnectionState != ConnectionState.Connected, "the host to see its link cut", WaitLimit);
            }
            if (random.Next(2) == 0)
            {
                await requests.ReleaseHeldAsync().WaitAsync(Limit);
            }
            else
            {
                Task reconnect = rig.RecoverAsync(w);
                await Task.Delay(random.Next(0, 50));
                await requests.ReleaseHeldAsync().WaitAsync(Limit);
                await reconnect.WaitAsync(WaitLimit);
            }
        }
        if (mode == Mode.Held && ur)
        {
            // The first attempt's script arrives now and replaces the program that streams.
            await Eventually.TrueAsync(() => rig.ExecutedIds.Count >= Actions / 3 || w.Bot.ConnectionState != ConnectionState.Connected, "a third of the program", WaitLimit);
            await front.ReleaseHeldAsync().WaitAsync(Limit);
        }
        int recoveries = await rig.RunToCompletionAsync(w, WaitLimit, maxRecoveries: 50);

        Assert.True(w.Executed.SequenceEqual(Enumerable.Range(1, Actions)), $"the host saw {w.Executed.Count} executions, {w.Executed.Distinct().Count()} distinct");
        IReadOnlyList<int> log = rig.ExecutedIds;
        Assert.True(log.SequenceEqual(Enumerable.Range(1, Actions)), $"the controller ran {log.Count}, {log.Distinct().Count()} distinct");
        Assert.True(rig.Position.IsSimilar(end, 1e-6), $"{brand} ended at {rig.Position}, expected {end}");
        Assert.Empty(rig.Errors);
        await w.Bot.DisconnectAsync();
        return recoveries;
    }

    /// <summary>The proxy in front of the controller's ports for a mode (channel 0: the driver, or UR's script port).</summary>
    private static FaultProxyOptions FrontOptions(string brand, int seed, Mode mode, Random random)
    {
        bool ur = brand == "UR";
        // On UR closes and garbage hit RTDE (channel 1): its driver link does not pass this proxy, and its script port only
        // carries the upload and the robot messages.
        int channel = ur ? 1 : 0;
        (int, int) streaming = ur ? (1_000, 40_000) : brand == "ABB" ? (100, 6_000) : (450, 20_000);
        byte[] garbage = System.Text.Encoding.ASCII.GetBytes(brand switch { "ABB" => "#garbage;", "KUKA" => "<Garbage></Garbage>", _ => "\0\u0003garbage" });
        return mode switch
        {
            Mode.Close => new() { Seed = seed, FaultChannel = channel, CloseConnections = random.Next(1, 4), CloseAfterBytes = [streaming] },
            Mode.Stall => new() { Seed = seed, Holdable = !ur },
            Mode.Delay => new() { Seed = seed, MaxDelay = TimeSpan.FromMilliseconds(random.Next(1, 4)) },
            Mode.Bytes => new() { Seed = seed, SplitIntoBytes = true },
            Mode.Garbage => new() { Seed = seed, FaultChannel = channel, GarbageConnections = random.Next(1, 3), CloseAfterBytes = [streaming], Garbage = garbage },
            Mode.Held => ur ? new() { Seed = seed, HoldConnections = 1 } : new() { Seed = seed, HoldConnections = 1, HoldAfterBytes = random.Next(0, 2_000) },
            _ => new()
            {
                Seed = seed, FaultChannel = channel, Holdable = !ur, CloseConnections = 1, GarbageConnections = 1, CloseAfterBytes = [streaming],
                Garbage = garbage, MaxDelay = TimeSpan.FromMilliseconds(1),
            },
        };
    }
}
