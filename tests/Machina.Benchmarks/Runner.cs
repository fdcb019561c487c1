using System.Diagnostics;
using System.Runtime.CompilerServices;

namespace Machina.Benchmarks;

/// <summary>Times a scenario: warm-up runs, then measured runs with a full collection before each; reports the median.</summary>
internal sealed class Runner(int warmups, int runs, Action<string> progress)
{
    private const double MinWarmupSeconds = 0.5;
    private const int MaxWarmups = 50;

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
        Func<object?> work = scenario.Prepare(size);
        // At least the requested warm-ups, and at least MinWarmupSeconds of them (up to MaxWarmups) so that small sizes also
        // run fully optimised code: the JIT recompiles hot methods after about 30 calls and a short delay.
        long warmupStart = Stopwatch.GetTimestamp();
        for (int i = 0; i < warmups || (i > 0 && i < MaxWarmups && Stopwatch.GetElapsedTime(warmupStart).TotalSeconds < MinWarmupSeconds); i++)
        {
            progress($"{scenario.Name} x {size:N0}: warm-up {i + 1}");
            work();
        }
        var samples = new List<Sample>();
        for (int i = 0; i < runs; i++)
        {
            progress($"{scenario.Name} x {size:N0}: run {i + 1}/{runs}");
            samples.Add(RunOnce(work, scenario.MultiThreaded));
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

    /// <summary>One timed run. Kept out of line so that the result cannot stay reachable from the caller's frame afterwards.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static Sample RunOnce(Func<object?> work, bool multiThreaded)
    {
        long baseline = FullCollect();
        int gen0 = GC.CollectionCount(0), gen1 = GC.CollectionCount(1), gen2 = GC.CollectionCount(2);
        TimeSpan pauseBefore = GC.GetTotalPauseDuration();
        TimeSpan cpuBefore = Process.GetCurrentProcess().TotalProcessorTime;
        long threadBefore = GC.GetAllocatedBytesForCurrentThread();
        long totalBefore = GC.GetTotalAllocatedBytes(precise: true);
        long faultsBefore = Machine.MinorPageFaults();
        long start = Stopwatch.GetTimestamp();
        object? result;
        long peak;
        using (var sampler = new PeakMemory(TimeSpan.FromMilliseconds(5)))
        {
            result = work();
            peak = sampler.Peak;
        }
        TimeSpan elapsed = Stopwatch.GetElapsedTime(start);
        long faults = Machine.MinorPageFaults() - faultsBefore;
        long threadAfter = GC.GetAllocatedBytesForCurrentThread();
        long totalAfter = GC.GetTotalAllocatedBytes(precise: true);
        TimeSpan cpuAfter = Process.GetCurrentProcess().TotalProcessorTime;
        var collections = $"{GC.CollectionCount(0) - gen0}/{GC.CollectionCount(1) - gen1}/{GC.CollectionCount(2) - gen2}";
        double pause = (GC.GetTotalPauseDuration() - pauseBefore).TotalSeconds;
        long retained = Math.Max(0, FullCollect() - baseline);
        GC.KeepAlive(result);
        return new Sample(elapsed.TotalSeconds, (cpuAfter - cpuBefore).TotalSeconds,
            multiThreaded ? totalAfter - totalBefore : threadAfter - threadBefore, retained, Math.Max(0, peak - baseline), collections, pause, faults);
    }

    private readonly record struct Sample(double Seconds, double CpuSeconds, long Allocated, long Retained, long Peak, string Collections, double GcPauseSeconds, long PageFaults);

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
