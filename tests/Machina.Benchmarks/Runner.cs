using System.Diagnostics;
using System.Runtime.CompilerServices;

namespace Machina.Benchmarks;

/// <summary>Times a scenario: warm-up runs, then measured runs with a full collection before each; reports the median.</summary>
/// <remarks>
/// The harness's event listeners (<see cref="RunListeners"/>; <paramref name="listeners"/>, by default as the environment asks) are
/// made before the scenario's <c>Prepare</c>, when no other thread runs. A measured run in which the JIT compiled any method is run
/// again, at most <c>runs</c> times in all; the row keeps the runs that compiled nothing, and is marked "(busy)" when it had to keep
/// one that did.
/// </remarks>
internal sealed class Runner(int warmups, int runs, Action<string> progress, bool settle = true, Func<RunListeners>? listeners = null)
{
    private const double MinWarmupSeconds = 0.5;
    private const int MaxWarmups = 50;

    /// <summary>At most this many warm-ups, and this long, are run waiting for the JIT to settle (a warm-up that compiles no method).</summary>
    private const int MaxSettleWarmups = 15;

    private const double MaxSettleSeconds = 20;

    public Measurement Run(Scenario scenario, int size)
    {
        if (scenario.Unavailable() is string why)
        {
            return Measurement.Skipped(scenario, size, "not available", why);
        }
        try
        {
            return Measure(scenario, size);
        }
        catch (Exception ex) when (ex is NotSupportedException or NotImplementedException)
        {
            return Measurement.Skipped(scenario, size, "not available", ex.Message);
        }
        catch (Exception ex)
        {
            return Measurement.Skipped(scenario, size, "error", $"{ex.GetType().Name}: {ex.Message}");
        }
        finally
        {
            try
            {
                scenario.Cleanup();
            }
            catch (Exception ex)
            {
                Console.Error.WriteLine($"{scenario.Name}: cleaning up failed: {ex.GetType().Name}: {ex.Message}");
            }
        }
    }

    private Measurement Measure(Scenario scenario, int size)
    {
        progress($"{scenario.Name} x {size:N0}: preparing");
        // Before Prepare starts the scenario's threads (see RunListeners: made beside them, a listener could deadlock with them).
        using RunListeners listening = (listeners ?? RunListeners.FromEnvironment)();
        Func<object?> work = scenario.Prepare(size);
        bool byThread = Environment.GetEnvironmentVariable("MACHINA_BENCH_THREADS") == "1";
        if (warmups > 0)
        {
            WarmBookkeeping(scenario.MultiThreaded, byThread, size);
            // Not with --quick (no settling): a check that every scenario works needs no promoted code.
            double small = settle ? WarmOncePerRun(scenario.SmallRun()) : 0;
            if (byThread && small > 0)
            {
                Console.Error.WriteLine($"{scenario.Name}: {OncePerRunRounds * 16} small runs in {small:0.0} s");
            }
        }
        (int warmedUp, bool settled) = WarmUp(scenario, size, work, listening, byThread);
        if (byThread)
        {
            Console.Error.WriteLine($"{scenario.Name}: {warmedUp} warm-up(s); the JIT {(settled ? "settled" : "was still compiling after the last")}");
        }
        listening.Clear();
        JitMethods? compiled = listening.Compiled;
        AllocationTypes? types = listening.Types;
        var samples = new List<Sample>();
        for (int i = 0; i < runs + RepeatedRuns(samples); i++)
        {
            progress($"{scenario.Name} x {size:N0}: run {i + 1}/{runs}");
            // Read outside the timed run (reading /proc costs processor time of its own).
            Dictionary<int, ThreadCpu.ThreadTime> threadsBefore = ThreadCpu.Read();
            JitActivity jitBefore = JitActivity.Now();
            listening.Count(true);
            Sample sample = RunOnce(work, scenario.MultiThreaded, byThread);
            listening.Count(false);
            JitActivity jit = JitActivity.Now().Since(jitBefore);
            List<ThreadCpu.ThreadTime> threads = ThreadCpu.Difference(threadsBefore, ThreadCpu.Read());
            samples.Add(sample with { JitSeconds = JitSeconds(threads, jit), JitMethods = jit.Methods });
            if (byThread)
            {
                // The threads as read inside the run (after its baseline collection, before the last): the harness's own
                // collections, on the issuing thread, are not in them; the JIT's column above keeps the reading around the run.
                Console.Error.WriteLine($"{scenario.Name} run {i + 1}: {jit.Methods} methods compiled{(jit.Methods > 0 && samples.Count(s => s.JitMethods > 0) <= runs ? " (run again)" : "")}; "
                    + $"processor time by thread: {ThreadCpu.Text(sample.Threads ?? threads, size)}");
            }
            if (compiled is not null)
            {
                Console.Error.WriteLine($"{scenario.Name} run {i + 1}: methods the JIT compiled (wall ms from start to end of each, costliest first):");
                foreach (string line in compiled.Drain(int.TryParse(Environment.GetEnvironmentVariable("MACHINA_BENCH_JIT_TOP"), out int top) ? top : 40))
                {
                    Console.Error.WriteLine(line);
                }
            }
        }
        int repeated = samples.Count - runs;
        samples = Kept(samples, runs);
        if (types is not null)
        {
            Console.Error.WriteLine($"{scenario.Name}: allocations by type (sampled) over the {runs + repeated} measured run(s):");
            foreach (string line in types.Lines((long)size * (runs + repeated)))
            {
                Console.Error.WriteLine(line);
            }
        }
        var status = "info";
        var measurement = new Measurement
        {
            Scenario = scenario.Name,
            Title = scenario.Title,
            Unit = scenario.Unit,
            Size = size,
            Runs = runs,
            MedianSeconds = Median(samples.Select(s => s.Seconds)),
            MinSeconds = samples.Min(s => s.Seconds),
            MaxSeconds = samples.Max(s => s.Seconds),
            CpuSeconds = Median(samples.Select(s => s.CpuSeconds)),
            JitSeconds = Median(samples.Select(s => s.JitSeconds)),
            CpuWithoutJitSeconds = Median(samples.Select(s => s.CpuSeconds - s.JitSeconds)),
            JitMethods = Median(samples.Select(s => s.JitMethods)),
            Warmups = warmedUp,
            JitSettled = samples.All(s => s.JitMethods == 0),
            RepeatedRuns = repeated,
            Collections = samples.OrderBy(s => s.Seconds).ElementAt(samples.Count / 2).Collections,
            GcPauseSeconds = samples.OrderBy(s => s.Seconds).ElementAt(samples.Count / 2).GcPauseSeconds,
            PageFaults = samples.OrderBy(s => s.Seconds).ElementAt(samples.Count / 2).PageFaults,
            AllocatedBytes = Median(samples.Select(s => s.Allocated)),
            RetainedBytes = Median(samples.Select(s => s.Retained)),
            PeakBytes = Median(samples.Select(s => s.Peak)),
            Target = scenario.Target,
        };
        if (measurement.TimeRatio is double timeRatio)
        {
            status = timeRatio <= 1 && (measurement.AllocationRatio ?? 0) <= 1 ? "met" : "missed";
        }
        return measurement with { Status = status };
    }

    /// <summary>
    /// The warm-up runs: at least the requested number, and at least <see cref="MinWarmupSeconds"/> of them (up to
    /// <see cref="MaxWarmups"/>) so that small sizes also run optimised code; then more until a run in which the JIT compiled no
    /// method at all (<see cref="JitActivity"/>, every thread): the JIT promotes a method after 30 calls and again with the profile
    /// it gathered, so code that runs a few times per run (connecting, the harness) is still being compiled runs later. Each goes
    /// through the measured runs' own path (<see cref="RunOnce"/>, the listeners recording), so that a measured run calls no code
    /// the warm-ups did not. Returns how many ran and whether the JIT settled; none with <c>--warmup 0</c>, and no waiting for the
    /// JIT without <c>settle</c> (<c>--quick</c>).
    /// </summary>
    private (int Count, bool Settled) WarmUp(Scenario scenario, int size, Func<object?> work, RunListeners listening, bool byThread)
    {
        long start = Stopwatch.GetTimestamp();
        bool settled = false;
        int i = 0;
        for (; i < warmups || (i > 0 && !Enough(i, settled)); i++)
        {
            progress($"{scenario.Name} x {size:N0}: warm-up {i + 1}");
            Dictionary<int, ThreadCpu.ThreadTime> threadsBefore = ThreadCpu.Read();
            JitActivity jitBefore = JitActivity.Now();
            listening.Count(true);
            Sample sample = RunOnce(work, scenario.MultiThreaded, byThread);
            listening.Count(false);
            JitActivity jit = JitActivity.Now().Since(jitBefore);
            _ = JitSeconds(ThreadCpu.Difference(threadsBefore, ThreadCpu.Read()), jit) + ThreadCpu.Text(sample.Threads ?? [], size).Length;
            settled = jit.Methods == 0;
        }
        return (i, settled);

        bool Enough(int done, bool settled)
        {
            double seconds = Stopwatch.GetElapsedTime(start).TotalSeconds;
            bool minimum = done >= MaxWarmups || seconds >= MinWarmupSeconds;
            return minimum && (!settle || settled || done >= warmups + MaxSettleWarmups || seconds >= MaxSettleSeconds);
        }
    }

    /// <summary>How many measured runs are run again: one for each that compiled a method (<see cref="Sample.JitMethods"/>), at most as many as the runs asked for.</summary>
    private int RepeatedRuns(List<Sample> samples) => Math.Min(runs, samples.Count(s => s.JitMethods > 0));

    /// <summary>
    /// The <paramref name="count"/> runs a row reports: those in which the JIT compiled nothing, in order; when fewer, the last of
    /// those that compiled make up the number.
    /// </summary>
    internal static List<Sample> Kept(List<Sample> samples, int count)
    {
        List<Sample> kept = [.. samples.Where(s => s.JitMethods == 0).Take(count)];
        if (kept.Count < count)
        {
            kept.AddRange(samples.Where(s => s.JitMethods > 0).TakeLast(count - kept.Count));
        }
        return kept;
    }

    /// <summary>
    /// Runs the harness's own per-run bookkeeping (a run of no work without its forced collections: the memory sampler, the
    /// processor-time and per-thread readings and their text) <see cref="BookkeepingRounds"/> times before the warm-ups, pausing between rounds so
    /// that the JIT's background promotions land: it runs a few times per run, so without this its code (and the BCL code only it
    /// calls: LINQ over the thread readings, /proc's enumeration) crossed the JIT's 30-call thresholds inside the measured runs, and
    /// the JIT's thread compiled the harness during them (about 29 % of the methods compiled in 8 measured `plain-kuka` runs).
    /// </summary>
    private static void WarmBookkeeping(bool multiThreaded, bool byThread, int size)
    {
        for (int round = 0; round < BookkeepingRounds; round++)
        {
            for (int i = 0; i < 16; i++)
            {
                Dictionary<int, ThreadCpu.ThreadTime> before = ThreadCpu.Read();
                JitActivity jitBefore = JitActivity.Now();
                Sample sample = RunOnce(static () => null, multiThreaded, byThread, collect: false);
                List<ThreadCpu.ThreadTime> threads = ThreadCpu.Difference(before, ThreadCpu.Read());
                _ = JitSeconds(threads, JitActivity.Now().Since(jitBefore)) + ThreadCpu.Text(sample.Threads ?? threads, size).Length;
            }
            Thread.Sleep(150); // the JIT promotes in the background after a 100 ms quiet spell
        }
    }

    /// <summary>Rounds of 16 bookkeeping passes: past both of the JIT's promotions (30 calls each) of code called once per pass.</summary>
    private const int BookkeepingRounds = 6;

    /// <summary>
    /// Runs the scenario's small run (<see cref="Scenario.SmallRun"/>) <see cref="OncePerRunRounds"/> x 16 times, pausing
    /// between rounds as <see cref="WarmBookkeeping"/> does: the code a run calls once is promoted here. A full-size warm-up
    /// calls it once, so the measured runs (runs 10-20 of a row) fell where its promotions do (30 and 60 calls): in `plain-kuka`
    /// 6-87 methods compiled in each measured run, the connect's, the twins' accept's and the event pump's (session 36).
    /// </summary>
    /// <returns>The seconds it took, 0 without a small run.</returns>
    private static double WarmOncePerRun(Action? smallRun)
    {
        if (smallRun is null)
        {
            return 0;
        }
        long start = Stopwatch.GetTimestamp();
        for (int round = 0; round < OncePerRunRounds; round++)
        {
            for (int i = 0; i < 16; i++)
            {
                smallRun();
            }
            Thread.Sleep(150); // the JIT promotes in the background after a 100 ms quiet spell
        }
        return Stopwatch.GetElapsedTime(start).TotalSeconds;
    }

    /// <summary>Rounds of 16 small runs: past both promotions (30 calls each) of code a run calls once, with room to spare.</summary>
    internal const int OncePerRunRounds = 5;

    /// <summary>The JIT's processor time in a run: its tiered-compilation thread's, or where /proc is missing the compiling time the runtime counted.</summary>
    private static double JitSeconds(List<ThreadCpu.ThreadTime> threads, JitActivity jit) =>
        threads.Count > 0 ? ThreadCpu.Jit(threads) : jit.Time.TotalSeconds;

    /// <summary>One timed run. Kept out of line so that the result cannot stay reachable from the caller's frame afterwards.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    /// <remarks>
    /// With <paramref name="byThread"/>, the threads' processor time is read after the baseline collection and before the
    /// collection that measures what is retained, outside the processor-time span (reading /proc costs time of its own), so
    /// that the issuing thread's figure is the work's and not the harness's forced collections'.
    /// </remarks>
    private static Sample RunOnce(Func<object?> work, bool multiThreaded, bool byThread, bool collect = true)
    {
        // The sampler's thread starts and stops outside the measured span (a thread start is about 0.1 ms).
        using var sampler = new PeakMemory(TimeSpan.FromMilliseconds(5));
        long baseline = collect ? FullCollect() : 0;
        Dictionary<int, ThreadCpu.ThreadTime>? threadsBefore = byThread ? ThreadCpu.Read() : null;
        sampler.Reset();
        int gen0 = GC.CollectionCount(0), gen1 = GC.CollectionCount(1), gen2 = GC.CollectionCount(2);
        TimeSpan pauseBefore = GC.GetTotalPauseDuration();
        TimeSpan cpuBefore = Process.GetCurrentProcess().TotalProcessorTime;
        long threadBefore = GC.GetAllocatedBytesForCurrentThread();
        long totalBefore = GC.GetTotalAllocatedBytes(precise: true);
        long faultsBefore = Machine.MinorPageFaults();
        long start = Stopwatch.GetTimestamp();
        object? result;
        long peak;
        result = work();
        peak = sampler.Peak;
        TimeSpan elapsed = Stopwatch.GetElapsedTime(start);
        long faults = Machine.MinorPageFaults() - faultsBefore;
        long threadAfter = GC.GetAllocatedBytesForCurrentThread();
        long totalAfter = GC.GetTotalAllocatedBytes(precise: true);
        TimeSpan cpuAfter = Process.GetCurrentProcess().TotalProcessorTime;
        var collections = $"{GC.CollectionCount(0) - gen0}/{GC.CollectionCount(1) - gen1}/{GC.CollectionCount(2) - gen2}";
        double pause = (GC.GetTotalPauseDuration() - pauseBefore).TotalSeconds;
        List<ThreadCpu.ThreadTime>? threads = threadsBefore is null ? null : ThreadCpu.Difference(threadsBefore, ThreadCpu.Read());
        long retained = collect ? Math.Max(0, FullCollect() - baseline) : 0;
        GC.KeepAlive(result);
        return new Sample(elapsed.TotalSeconds, (cpuAfter - cpuBefore).TotalSeconds,
            multiThreaded ? totalAfter - totalBefore : threadAfter - threadBefore, retained, Math.Max(0, peak - baseline), collections, pause, faults)
        {
            Threads = threads,
        };
    }

    internal readonly record struct Sample(double Seconds, double CpuSeconds, long Allocated, long Retained, long Peak, string Collections, double GcPauseSeconds, long PageFaults)
    {
        /// <summary>The JIT's processor time during the run (see <see cref="JitSeconds(List{ThreadCpu.ThreadTime}, JitActivity)"/>).</summary>
        public double JitSeconds { get; init; }

        /// <summary>Methods the JIT compiled during the run.</summary>
        public long JitMethods { get; init; }

        /// <summary>Each thread's processor time inside the run (between its two collections), when asked for; else null.</summary>
        public List<ThreadCpu.ThreadTime>? Threads { get; init; }
    }

    private static long FullCollect()
    {
        GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
        GC.WaitForPendingFinalizers();
        GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
        return GC.GetTotalMemory(forceFullCollection: false);
    }

    private static T Median<T>(IEnumerable<T> values)
    {
        var sorted = values.Order().ToList();
        return sorted[sorted.Count / 2];
    }
}
