namespace Machina.Benchmarks;

/// <summary>
/// Samples the managed heap size every few milliseconds on a timer thread while a run is going and keeps the largest value,
/// to show whether memory stays flat (streaming, compiling to files) or grows with the size (compiling in memory).
/// </summary>
internal sealed class PeakMemory : IDisposable
{
    private readonly Timer _timer;
    private long _peak;

    public PeakMemory(TimeSpan period)
    {
        _peak = GC.GetTotalMemory(forceFullCollection: false);
        _timer = new Timer(_ => Sample(), null, TimeSpan.Zero, period);
    }

    /// <summary>The largest heap size seen so far, in bytes.</summary>
    public long Peak
    {
        get
        {
            Sample();
            return Interlocked.Read(ref _peak);
        }
    }

    private void Sample()
    {
        long now = GC.GetTotalMemory(forceFullCollection: false);
        long seen = Interlocked.Read(ref _peak);
        while (now > seen)
        {
            long previous = Interlocked.CompareExchange(ref _peak, now, seen);
            if (previous == seen)
            {
                break;
            }
            seen = previous;
        }
    }

    public void Dispose() => _timer.Dispose();
}
