namespace Machina.Benchmarks;

/// <summary>What one whole-process scenario measured: times from outside the child, its own cold and warm work, peak memory, and the target.</summary>
internal sealed record ProcessResult(string Scenario, string Title, int Size)
{
    /// <summary>Wall time of each child process, from just before it was started until it had exited, seconds.</summary>
    public List<double> ProcessSeconds { get; init; } = [];

    /// <summary>Median time from process start to Main.</summary>
    public double StartupSeconds { get; init; }

    /// <summary>Median of the first (cold) run of the work inside each child.</summary>
    public double ColdWorkSeconds { get; init; }

    /// <summary>Fastest later repetition of the work in one child (JIT and memory warmed up), or null when not measured.</summary>
    public double? WarmWorkSeconds { get; init; }

    /// <summary>Median processor time of the children (all threads, start-up included): less disturbed by other load than wall time.</summary>
    public double CpuSeconds { get; init; }

    /// <summary>Largest peak resident memory (VmHWM) of the children.</summary>
    public long PeakResidentBytes { get; init; }

    /// <summary>The target, in the words.</summary>
    public string TargetText { get; init; } = "-";

    /// <summary>Measured over target for the main figure (at most 1 meets it).</summary>
    public double? Ratio { get; init; }

    /// <summary>Measured over target for the second figure (memory, or latency), or null.</summary>
    public double? SecondRatio { get; init; }

    /// <summary>Scenario-specific figures (rate, latency percentiles…), already formatted.</summary>
    public string Note { get; init; } = "";

    /// <summary>Error message when the scenario failed.</summary>
    public string? Error { get; init; }

    public string Status => Error is not null ? "error" : Ratio is null ? "info" : Ratio <= 1 && (SecondRatio ?? 0) <= 1 ? "met" : "missed";

    public double Median => Percentile(ProcessSeconds, 0.5);

    public double Min => ProcessSeconds.Count == 0 ? double.NaN : ProcessSeconds.Min();

    public double Max => ProcessSeconds.Count == 0 ? double.NaN : ProcessSeconds.Max();

    /// <summary>The value at fraction <paramref name="p"/> of the sorted values (nearest rank; the median of an even count is the mean of the middle two).</summary>
    public static double Percentile(IReadOnlyList<double> values, double p)
    {
        if (values.Count == 0)
        {
            return double.NaN;
        }
        double[] sorted = [.. values.Order()];
        if (p == 0.5 && sorted.Length % 2 == 0)
        {
            return (sorted[sorted.Length / 2 - 1] + sorted[sorted.Length / 2]) / 2;
        }
        int rank = (int)Math.Ceiling(p * sorted.Length) - 1;
        return sorted[Math.Clamp(rank, 0, sorted.Length - 1)];
    }
}
