using System.Diagnostics;

namespace Machina.Benchmarks;

/// <summary>Times a scenario: warm-up runs, then measured runs with a full collection before each; reports the median.</summary>
internal sealed class Runner(int warmups, int runs, Action<string> progress)
{
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
            scenario.Cleanup();
        }
    }

    private Measurement Measure(Scenario scenario, int size)
    {
        progress($"{scenario.Name} x {size:N0}: preparing");
        Func<object?> work = scenario.Prepare(size);
        for (int i = 0; i < warmups; i++)
        {
            progress($"{scenario.Name} x {size:N0}: warm-up {i + 1}/{warmups}");
            work();
        }
        var seconds = new List<double>();
        var allocated = new List<long>();
        var retained = new List<long>();
        for (int i = 0; i < runs; i++)
        {
            progress($"{scenario.Name} x {size:N0}: run {i + 1}/{runs}");
            long baseline = FullCollect();
            long threadBefore = GC.GetAllocatedBytesForCurrentThread();
            long totalBefore = GC.GetTotalAllocatedBytes(precise: true);
            long start = Stopwatch.GetTimestamp();
            object? result = work();
            TimeSpan elapsed = Stopwatch.GetElapsedTime(start);
            long threadAfter = GC.GetAllocatedBytesForCurrentThread();
            long totalAfter = GC.GetTotalAllocatedBytes(precise: true);
            seconds.Add(elapsed.TotalSeconds);
            allocated.Add(scenario.MultiThreaded ? totalAfter - totalBefore : threadAfter - threadBefore);
            retained.Add(Math.Max(0, FullCollect() - baseline));
            GC.KeepAlive(result);
        }
        var status = "info";
        var measurement = new Measurement
        {
            Scenario = scenario.Name,
            Title = scenario.Title,
            Unit = scenario.Unit,
            Size = size,
            Runs = runs,
            MedianSeconds = Median(seconds),
            MinSeconds = seconds.Min(),
            MaxSeconds = seconds.Max(),
            AllocatedBytes = Median(allocated),
            RetainedBytes = Median(retained),
            Target = scenario.Target,
        };
        if (measurement.TimeRatio is double timeRatio)
        {
            status = timeRatio <= 1 && (measurement.AllocationRatio ?? 0) <= 1 ? "met" : "missed";
        }
        return measurement with { Status = status };
    }

    private static long FullCollect()
    {
        GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
        GC.WaitForPendingFinalizers();
        GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
        return GC.GetTotalMemory(forceFullCollection: false);
    }

    private static T Median<T>(List<T> values)
    {
        var sorted = values.Order().ToList();
        return sorted[sorted.Count / 2];
    }
}
