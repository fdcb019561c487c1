using System.Diagnostics.Tracing;

namespace Machina.Benchmarks;

/// <summary>
/// With <c>gclog=1</c>, the child records each garbage collection the runtime reports (its number, generation, reason and type
/// at the start; the time from its start to its end), to see what triggers the collections of a job and how long each pauses.
/// </summary>
internal sealed class GcEventLog : EventListener
{
    private readonly List<string> _events = [];
    private readonly long _start = DateTime.UtcNow.Ticks;
    private long _gcStart;

    /// <summary>"ms:start:gen:reason:type" or "ms:end:ms taken" for each event so far.</summary>
    public List<string> Events()
    {
        lock (_events)
        {
            return [.. _events];
        }
    }

    protected override void OnEventSourceCreated(EventSource eventSource)
    {
        if (eventSource.Name == "Microsoft-Windows-DotNETRuntime")
        {
            EnableEvents(eventSource, EventLevel.Informational, (EventKeywords)0x1); // GC
        }
    }

    protected override void OnEventWritten(EventWrittenEventArgs e)
    {
        long now = e.TimeStamp.Ticks; // when the runtime wrote it (the listener gets it later, in batches)
        string? line = e.EventName switch
        {
            "GCStart_V2" => $"{TimeSpan.FromTicks(now - _start).TotalMilliseconds:0.0}:start:gen{e.Payload?[1]}:reason{e.Payload?[2]}:type{e.Payload?[3]}",
            "GCEnd_V1" => $"{TimeSpan.FromTicks(now - _start).TotalMilliseconds:0.0}:end:{TimeSpan.FromTicks(now - _gcStart).TotalMilliseconds:0.0}ms",
            "GCSuspendEEBegin_V1" or "GCRestartEEEnd_V1" or "BGCStart" or "BGC1stConEnd" or "BGC2ndNonConEnd" or "BGC2ndConEnd" or "BGCRevisit" or "BGCDrainMark" => $"{TimeSpan.FromTicks(now - _start).TotalMilliseconds:0.0}:{e.EventName}",
            _ => null,
        };
        if (e.EventName == "GCStart_V2")
        {
            _gcStart = now;
        }
        if (line is not null)
        {
            lock (_events)
            {
                _events.Add(line);
            }
        }
    }
}
