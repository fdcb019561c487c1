using System.Globalization;
using System.Text;

namespace Machina.Simulation;

/// <summary>
/// A diagnostic of the virtual UR's RTDE sender, measured inside the twin (issue 45: the 500 Hz period error beside a stream):
/// how late each due data package went out against its deadline on the controller's grid, split by whether a garbage
/// collection paused the process while the sender waited for it, and the process's collections and pause time since the
/// sender started. Off unless the environment variable <see cref="Variable"/> names a file: then the sender records, and the
/// summary is written to that file with the process id appended (<c>PATH.PID</c>) about once a second and when the sender
/// ends, so a twin that is killed leaves its last second's summary. Written by the sender's thread only; the summary is read
/// from a timer's thread without a lock (a diagnostic: a count may be one package behind).
/// </summary>
internal sealed class VirtualUrRtdeTiming : IDisposable
{
    /// <summary>The environment variable that turns the diagnostic on: the summary's file (the process id is appended).</summary>
    public const string Variable = "MACHINA_RTDE_TIMING";

    /// <summary>Buckets of 10 µs from 1 ms early to 20 ms late; the last counts everything later.</summary>
    private const int BucketMicroseconds = 10, EarliestMicroseconds = -1000, Buckets = 2101;

    private readonly long[] _quiet = new long[Buckets], _collected = new long[Buckets];
    private readonly double _microsecondsPerTick;
    private readonly TimeSpan _pauseAtStart;
    private readonly int[] _collectionsAtStart = new int[3];
    private readonly string? _file;
    private readonly bool _precise;
    private readonly Timer? _timer;
    private double _latest = double.NegativeInfinity;
    private long _woken;

    /// <summary>
    /// A recorder for a clock of <paramref name="timestampFrequency"/> ticks a second, writing to <paramref name="file"/> when given,
    /// for a sender whose wait is <paramref name="precise"/> (to the microsecond) or not (whole milliseconds).
    /// </summary>
    public VirtualUrRtdeTiming(long timestampFrequency, string? file, bool precise = false)
    {
        _precise = precise;
        _microsecondsPerTick = 1e6 / timestampFrequency;
        _pauseAtStart = GC.GetTotalPauseDuration();
        for (int g = 0; g < 3; g++)
        {
            _collectionsAtStart[g] = GC.CollectionCount(g);
        }
        _file = file;
        if (file is not null)
        {
            _timer = new Timer(static t => ((VirtualUrRtdeTiming)t!).Write(), this, TimeSpan.FromSeconds(1), TimeSpan.FromSeconds(1));
        }
    }

    /// <summary>The recorder the environment asks for (<see cref="Variable"/>), or null when it asks for none.</summary>
    public static VirtualUrRtdeTiming? FromEnvironment(long timestampFrequency, bool precise) =>
        Environment.GetEnvironmentVariable(Variable) is { Length: > 0 } path
            ? new VirtualUrRtdeTiming(timestampFrequency, path + "." + Environment.ProcessId.ToString(CultureInfo.InvariantCulture), precise)
            : null;

    /// <summary>The process's total garbage-collection pause so far (read before a wait, compared after it).</summary>
    public static TimeSpan PauseNow => GC.GetTotalPauseDuration();

    /// <summary>
    /// A due package went out <paramref name="lateTicks"/> after its deadline (negative: before it); <paramref name="collected"/>
    /// when a collection paused the process during the wait before it.
    /// </summary>
    public void Record(long lateTicks, bool collected)
    {
        double us = lateTicks * _microsecondsPerTick;
        int bucket = (int)Math.Clamp(Math.Floor((us - EarliestMicroseconds) / BucketMicroseconds), 0, Buckets - 1);
        (collected ? _collected : _quiet)[bucket]++;
        _latest = Math.Max(_latest, us);
    }

    /// <summary>The sender was woken before a deadline (a state change to report at once).</summary>
    public void Woken() => _woken++;

    /// <summary>The summary: packages, lateness percentiles and the share late by more than 0.5 and 1 ms, with and without a collection during the wait.</summary>
    public string Summary()
    {
        long[] quiet = (long[])_quiet.Clone(), collected = (long[])_collected.Clone();
        long[] all = new long[Buckets];
        for (int i = 0; i < Buckets; i++)
        {
            all[i] = quiet[i] + collected[i];
        }
        var text = new StringBuilder();
        var c = CultureInfo.InvariantCulture;
        text.Append(c, $"rtde sender lateness (send time - deadline, us; bucket {BucketMicroseconds} us; wait {(_precise ? "to the microsecond" : "in whole milliseconds")}): ");
        Line(text, "all", all);
        Line(text, "no GC during the wait", quiet);
        Line(text, "GC during the wait", collected);
        text.Append(c, $"max {_latest:0} us; woken early {_woken}; GCs since the sender started gen0 {GC.CollectionCount(0) - _collectionsAtStart[0]}, ");
        text.Append(c, $"gen1 {GC.CollectionCount(1) - _collectionsAtStart[1]}, gen2 {GC.CollectionCount(2) - _collectionsAtStart[2]}, ");
        text.Append(c, $"pause {(GC.GetTotalPauseDuration() - _pauseAtStart).TotalMilliseconds:0.0} ms; heap {GC.GetTotalMemory(false) / 1024} KB; ");
        using (var process = System.Diagnostics.Process.GetCurrentProcess())
        {
            text.Append(c, $"process cpu {process.TotalProcessorTime.TotalMilliseconds:0} ms, peak working set {process.PeakWorkingSet64 / (1024 * 1024)} MB");
        }
        return text.ToString();
    }

    private static void Line(StringBuilder text, string name, long[] buckets)
    {
        long n = buckets.Sum();
        var c = CultureInfo.InvariantCulture;
        text.Append(c, $"{name}: {n} packages");
        if (n > 0)
        {
            text.Append(c, $", p50 {Percentile(buckets, n, 0.5)}, p90 {Percentile(buckets, n, 0.9)}, p99 {Percentile(buckets, n, 0.99)}, p99.9 {Percentile(buckets, n, 0.999)}");
            text.Append(c, $", late > 0.5 ms {Above(buckets, 500)}, > 1 ms {Above(buckets, 1000)}, > 2 ms {Above(buckets, 2000)}");
        }
        text.Append("; ");
    }

    /// <summary>The upper edge (µs) of the bucket that holds the <paramref name="q"/> quantile.</summary>
    private static int Percentile(long[] buckets, long n, double q)
    {
        long rank = (long)Math.Ceiling(q * n), seen = 0;
        for (int i = 0; i < buckets.Length; i++)
        {
            seen += buckets[i];
            if (seen >= rank)
            {
                return EarliestMicroseconds + ((i + 1) * BucketMicroseconds);
            }
        }
        return int.MaxValue;
    }

    private static long Above(long[] buckets, int microseconds)
    {
        long count = 0;
        for (int i = (microseconds - EarliestMicroseconds) / BucketMicroseconds; i < buckets.Length; i++)
        {
            count += buckets[i];
        }
        return count;
    }

    /// <summary>Writes the summary to the file (a write that fails is left: the next tries again).</summary>
    public void Write()
    {
        if (_file is null)
        {
            return;
        }
        try
        {
            File.WriteAllText(_file, Summary() + Environment.NewLine);
        }
        catch (IOException)
        {
        }
        catch (UnauthorizedAccessException)
        {
        }
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        _timer?.Dispose();
        Write();
    }
}
