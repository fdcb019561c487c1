using System.Collections.Concurrent;
using System.Diagnostics.Tracing;

namespace Machina.Benchmarks;

/// <summary>
/// Which types a scenario allocates (<c>MACHINA_BENCH_ALLOCS=1</c>): the runtime reports a sampled allocation about every 100 KB
/// allocated (<c>GCAllocationTick</c>) with the type of the object that crossed the mark, so the bytes per type are estimates
/// (good to a few bytes per unit over 10^4 units or more). Counts only while <see cref="Counting"/>: around each run's work.
/// </summary>
internal sealed class AllocationTypes : EventListener
{
    /// <summary>Bytes the runtime means by one sampled allocation event.</summary>
    private const long BytesPerTick = 100 * 1024;

    private readonly ConcurrentDictionary<string, long> _bytes = new();

    /// <summary>Whether allocation events are counted now.</summary>
    public volatile bool Counting;

    protected override void OnEventSourceCreated(EventSource source)
    {
        if (source.Name == "Microsoft-Windows-DotNETRuntime")
        {
            EnableEvents(source, EventLevel.Verbose, (EventKeywords)0x1); // GC keyword: GCAllocationTick is verbose
        }
    }

    protected override void OnEventWritten(EventWrittenEventArgs e)
    {
        if (Counting && e.EventName?.StartsWith("GCAllocationTick", StringComparison.Ordinal) == true
            && e.PayloadNames?.IndexOf("TypeName") is int index and >= 0 && e.Payload?[index] is string type)
        {
            _bytes.AddOrUpdate(type, BytesPerTick, (_, bytes) => bytes + BytesPerTick);
        }
    }

    /// <summary>Forgets the bytes counted so far (the warm-ups').</summary>
    public void Clear() => _bytes.Clear();

    /// <summary>"type: bytes per unit" lines, largest first, for <paramref name="units"/> units counted.</summary>
    public IEnumerable<string> Lines(long units, int top = 15) => _bytes.OrderByDescending(p => p.Value).Take(top)
        .Select(p => $"  {p.Key}: {Report.Bytes((double)p.Value / units)}/unit");
}
