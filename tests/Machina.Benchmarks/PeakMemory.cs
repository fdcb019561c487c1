namespace Machina.Benchmarks;

/// <summary>
/// Samples the managed heap size every few milliseconds on a sampling thread of its own while a run is going and keeps the
/// largest value, to show whether memory stays flat (streaming, compiling to files) or grows with the size (compiling in
/// memory). The thread sleeps in a kernel wait between samples: a <see cref="Timer"/> ran each sample on a thread-pool worker,
/// which then spun (<c>sched_yield</c>) before it slept, 200 times a second inside the measured processor time.
/// </summary>
internal sealed class PeakMemory : IDisposable
{
    private readonly ManualResetEvent _stop = new(false); // a kernel wait: no spinning before it sleeps
    private readonly Thread _sampler;
    private long _peak;

    public PeakMemory(TimeSpan period)
    {
        _peak = GC.GetTotalMemory(forceFullCollection: false);
        _sampler = new Thread(() =>
        {
            while (!_stop.WaitOne(period))
            {
                Sample();
            }
        })
        { IsBackground = true, Name = "Bench memory" };
        _sampler.Start();
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

    /// <summary>Starts over from the heap size now (the run's baseline, after its full collection).</summary>
    public void Reset() => Interlocked.Exchange(ref _peak, GC.GetTotalMemory(forceFullCollection: false));

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

    public void Dispose()
    {
        _stop.Set();
        _sampler.Join();
        _stop.Dispose();
    }
}
