namespace Machina.Benchmarks;

/// <summary>The outcome of one scenario at one size: median time of the measured runs, allocations, retained memory, verdict.</summary>
internal sealed record Measurement
{
    public required string Scenario { get; init; }
    public required string Title { get; init; }
    public required string Unit { get; init; }
    public required int Size { get; init; }
    public int Runs { get; init; }
    public double MedianSeconds { get; init; }
    public double MinSeconds { get; init; }
    public double MaxSeconds { get; init; }
    /// <summary>Processor time of the whole process during the median run (all threads, GC included); less sensitive to a busy machine than wall time.</summary>
    public double CpuSeconds { get; init; }
    /// <summary>Processor time of the JIT compiler during a measured run (median; its tiered-compilation thread), part of <see cref="CpuSeconds"/>.</summary>
    public double JitSeconds { get; init; }

    /// <summary>The median over the measured runs of the process's processor time less the JIT's: the steady state's cost.</summary>
    public double CpuWithoutJitSeconds { get; init; }

    /// <summary>Methods the JIT compiled during a measured run (median).</summary>
    public long JitMethods { get; init; }

    /// <summary>Warm-up runs before the measured ones.</summary>
    public int Warmups { get; init; }

    /// <summary>False when a measured run the row keeps compiled a method (the JIT had not settled; see <see cref="RepeatedRuns"/>).</summary>
    public bool JitSettled { get; init; } = true;

    /// <summary>Measured runs run again because the JIT compiled a method in them (at most <see cref="Runs"/>).</summary>
    public int RepeatedRuns { get; init; }

    /// <summary>Garbage collections of generations 0/1/2 during the median run, e.g. "12/3/1".</summary>
    public string Collections { get; init; } = "";

    /// <summary>Time the program was paused by the garbage collector during the median run.</summary>
    public double GcPauseSeconds { get; init; }

    /// <summary>Minor page faults of the process during the median run (first touches of fresh memory); 0 where unknown.</summary>
    public long PageFaults { get; init; }
    public long AllocatedBytes { get; init; }
    /// <summary>Memory still reachable after the run, the result included (e.g. the compiled program), over the heap before it.</summary>
    public long RetainedBytes { get; init; }

    /// <summary>The largest heap size seen during the run (sampled every 5 ms), over the heap before it.</summary>
    public long PeakBytes { get; init; }
    public Target? Target { get; init; }

    /// <summary>"met", "missed", "info" (no target), "not available" or "error".</summary>
    public string Status { get; init; } = "info";

    /// <summary>Why the scenario did not run, or what went wrong.</summary>
    public string? Note { get; init; }

    public double NanosecondsPerUnit => Size > 0 ? MedianSeconds * 1e9 / Size : 0;
    /// <summary>Processor time per unit (all threads) during the median run, ns.</summary>
    public double CpuNanosecondsPerUnit => Size > 0 ? CpuSeconds * 1e9 / Size : 0;
    /// <summary>Processor time per unit without the JIT's (see <see cref="CpuWithoutJitSeconds"/>), ns.</summary>
    public double CpuWithoutJitNanosecondsPerUnit => Size > 0 ? CpuWithoutJitSeconds * 1e9 / Size : 0;
    public double UnitsPerSecond => MedianSeconds > 0 ? Size / MedianSeconds : 0;
    public double BytesPerUnit => Size > 0 ? (double)AllocatedBytes / Size : 0;

    /// <summary>Measured time per unit over the target's (at most 1 means met; for throughput targets, target rate over measured rate).</summary>
    public double? TimeRatio => Target is null || Runs == 0 ? null
        : (Target.OnProcessorTime ? CpuNanosecondsPerUnit : NanosecondsPerUnit) / Target.NanosecondsPerUnit;

    /// <summary>Measured allocations per unit over the target's, when the target limits allocations.</summary>
    public double? AllocationRatio => Target?.BytesPerUnit is double limit && Runs > 0 ? BytesPerUnit / limit : null;

    public static Measurement Skipped(Scenario scenario, int size, string status, string note) => new()
    {
        Scenario = scenario.Name, Title = scenario.Title, Unit = scenario.Unit, Size = size, Target = scenario.Target, Status = status, Note = note,
    };
}
