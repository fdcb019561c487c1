using System.Collections.Concurrent;
using System.Diagnostics.Tracing;
using System.Globalization;

namespace Machina.Benchmarks;

/// <summary>
/// Which methods the JIT compiles during measured runs (<c>MACHINA_BENCH_JIT=1</c>), at which tier and for how long: the
/// runtime's <c>MethodJittingStarted</c> and <c>MethodLoadVerbose</c> events (JIT keyword). The time shown is the wall time
/// between the two on one thread: the compiling, plus any time the thread was not on a processor (on a loaded machine, a lot). Tells per-action code still being promoted (what every program pays) from code a run
/// calls a few times (connecting, disconnecting), which reaches the JIT's 30 calls only after as many runs. Also counts the
/// exceptions thrown in the run (<c>ExceptionThrown_V1</c>, exception keyword): each is paid, and its handling code compiled, per throw.
/// </summary>
internal sealed class JitMethods : EventListener
{
    private readonly ConcurrentDictionary<long, (string Name, DateTime Start)> _started = new();
    private readonly ConcurrentQueue<(string Name, string Tier, double Milliseconds)> _compiled = new();
    private readonly ConcurrentQueue<string> _thrown = new();

    /// <summary>Whether compiled methods are recorded now.</summary>
    public volatile bool Counting;

    protected override void OnEventSourceCreated(EventSource source)
    {
        if (source.Name == "Microsoft-Windows-DotNETRuntime")
        {
            EnableEvents(source, EventLevel.Verbose, (EventKeywords)(0x10 | 0x8000)); // JIT and exception keywords
        }
    }

    protected override void OnEventWritten(EventWrittenEventArgs e)
    {
        if (!Counting || e.EventName is not string name || e.Payload is null || e.PayloadNames is null)
        {
            return;
        }
        if (name.StartsWith("ExceptionThrown", StringComparison.Ordinal))
        {
            if (Value(e, "ExceptionType") is string type) // not the event that marks the throw's end
            {
                _thrown.Enqueue($"{type}: {Value(e, "ExceptionMessage")}");
            }
        }
        else if (name.StartsWith("MethodJittingStarted", StringComparison.Ordinal))
        {
            _started[e.OSThreadId] = (Name(e), e.TimeStamp);
        }
        else if (name.StartsWith("MethodLoadVerbose", StringComparison.Ordinal))
        {
            double ms = _started.TryRemove(e.OSThreadId, out var start) ? (e.TimeStamp - start.Start).TotalMilliseconds : 0;
            int flags = Convert.ToInt32(Value(e, "MethodFlags") ?? 0, CultureInfo.InvariantCulture);
            _compiled.Enqueue((Name(e), Tier((flags >> 7) & 0x7), ms));
        }
    }

    /// <summary>Forgets what was recorded so far (the warm-ups').</summary>
    public void Clear()
    {
        _compiled.Clear();
        _thrown.Clear();
        _started.Clear();
    }

    /// <summary>What was recorded since the last call, as lines: the count and time by tier, the exceptions thrown (when any), then the costliest methods.</summary>
    public IEnumerable<string> Drain(int top = 40)
    {
        var all = new List<(string Name, string Tier, double Milliseconds)>();
        while (_compiled.TryDequeue(out var m))
        {
            all.Add(m);
        }
        yield return "  by tier: " + string.Join(", ", all.GroupBy(m => m.Tier).OrderByDescending(g => g.Count())
            .Select(g => string.Create(CultureInfo.InvariantCulture, $"{g.Key} {g.Count()} ({g.Sum(m => m.Milliseconds):0.0} ms)")));
        var thrown = new List<string>();
        while (_thrown.TryDequeue(out string? t))
        {
            thrown.Add(t);
        }
        if (thrown.Count > 0)
        {
            yield return $"  exceptions thrown: {thrown.Count}" + string.Concat(thrown.GroupBy(t => t).OrderByDescending(g => g.Count())
                .Select(g => string.Create(CultureInfo.InvariantCulture, $"; {g.Count()} x {g.Key}")));
        }
        foreach (var m in all.OrderByDescending(m => m.Milliseconds).Take(top))
        {
            yield return string.Create(CultureInfo.InvariantCulture, $"  {m.Milliseconds,7:0.00} ms {m.Tier,-16} {m.Name}");
        }
    }

    private static object? Value(EventWrittenEventArgs e, string field) =>
        e.PayloadNames!.IndexOf(field) is int i and >= 0 ? e.Payload![i] : null;

    private static string Name(EventWrittenEventArgs e) => $"{Value(e, "MethodNamespace")}::{Value(e, "MethodName")}";

    /// <summary>The runtime's optimisation tier in a method's flags (bits 7-9).</summary>
    internal static string Tier(int tier) => tier switch
    {
        1 => "MinOpts",
        2 => "Optimized",
        3 => "Tier0",
        4 => "Tier1",
        5 => "Tier1-OSR",
        6 => "Tier0-instr",
        7 => "Tier1-instr",
        _ => "unknown",
    };
}
