namespace Machina.Simulation.Twin;

/// <summary>
/// A wait on a twin's own thread that blocks without spinning. Waiting on <c>Task.Delay(…).GetAwaiter().GetResult()</c>
/// spins the processor before it blocks, and a twin running many times faster than real time waits microseconds per
/// motion, so it spun all the time (20 native twins side by side kept a load average of 140 on two cores). On the system
/// clock, or the scaled clock of a faster-than-real-time twin over it, the wait is a kernel wait on the cancellation's
/// handle in whole milliseconds (the timer's resolution); what is under a millisecond is carried to the next wait, so a
/// run of short motions still takes its time in total. On any other <see cref="TimeProvider"/> (a fake clock in tests) it
/// is that provider's delay, as before.
/// </summary>
internal sealed class TwinSleep
{
    private long _owedTicks;

    /// <summary>Blocks for <paramref name="span"/> of <paramref name="time"/>; throws <see cref="OperationCanceledException"/> when cancelled.</summary>
    public void Wait(TimeProvider time, TimeSpan span, CancellationToken cancellation)
    {
        cancellation.ThrowIfCancellationRequested();
        double scale = 1;
        TimeProvider inner = time;
        if (time is TwinScaledTime scaled)
        {
            (inner, scale) = (scaled.Inner, scaled.Factor);
        }
        if (inner != TimeProvider.System)
        {
            TwinWait.Delay(span, time, cancellation);
            return;
        }
        long owed = Interlocked.Add(ref _owedTicks, (long)(span.Ticks / scale));
        long milliseconds = owed / TimeSpan.TicksPerMillisecond;
        if (milliseconds < 1)
        {
            return;
        }
        Interlocked.Add(ref _owedTicks, -milliseconds * TimeSpan.TicksPerMillisecond);
        TwinWait.Blocking();
        if (cancellation.WaitHandle.WaitOne(TimeSpan.FromMilliseconds(milliseconds)))
        {
            cancellation.ThrowIfCancellationRequested();
        }
    }
}
