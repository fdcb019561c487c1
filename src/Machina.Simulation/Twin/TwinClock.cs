namespace Machina.Simulation.Twin;

/// <summary>
/// The time of a twin controller. Motion and waits advance <see cref="Seconds"/>; in real-time mode they also take that long on the
/// <see cref="TimeProvider"/> (a fake provider in tests), otherwise they return at once (to verify a program quickly).
/// </summary>
internal sealed class TwinClock(TimeProvider time, bool realTime)
{
    private readonly TwinSleep _sleep = new();
    private long _ticks;

    /// <summary>The time source that real-time waits use.</summary>
    public TimeProvider Time { get; } = time;

    /// <summary>True when waits take their time on <see cref="Time"/>.</summary>
    public bool RealTime { get; } = realTime;

    /// <summary>Program time so far, in seconds: the sum of every motion and wait (a volatile read: atomic on every platform, as the interlocked additions that move it are).</summary>
    public double Seconds => Volatile.Read(ref _ticks) / (double)TimeSpan.TicksPerSecond;

    /// <summary>Advances the program time by <paramref name="seconds"/>, waiting for it in real-time mode.</summary>
    public void Wait(double seconds, CancellationToken cancellation)
    {
        cancellation.ThrowIfCancellationRequested();
        if (!(seconds > 0))
        {
            return;
        }
        TimeSpan span = Span(seconds);
        if (RealTime)
        {
            _sleep.Wait(Time, span, cancellation);
        }
        Interlocked.Add(ref _ticks, span.Ticks);
    }

    /// <summary>
    /// Waits <paramref name="seconds"/> (at most a day) on <see cref="Time"/> whatever the mode, adding nothing to the program
    /// time: a background task's wait, whose period is real and which moves no arm.
    /// </summary>
    public void WaitAside(double seconds, CancellationToken cancellation) =>
        _sleep.Wait(Time, Span(seconds), cancellation);

    /// <summary>
    /// Waits <paramref name="seconds"/> of the wall clock, not faster when the twin runs faster than real time, adding nothing to
    /// the program time: a background task's period (a monitor that reports every 20 ms reports every 20 ms at 1000× too,
    /// instead of 50,000 times a second).
    /// </summary>
    public void WaitWall(double seconds, CancellationToken cancellation) =>
        _sleep.Wait(TwinScaledTime.Wall(Time), Span(seconds), cancellation);

    /// <summary>A wait's length, capped at a day (a longer one is no use on a twin and would overflow the timer).</summary>
    private static TimeSpan Span(double seconds) => TimeSpan.FromSeconds(Math.Min(seconds, 86_400));

    /// <summary>Adds <paramref name="seconds"/> of program time that was already waited for (a motion that a hold cut into parts).</summary>
    public void Add(double seconds)
    {
        if (seconds > 0)
        {
            Interlocked.Add(ref _ticks, TimeSpan.FromSeconds(Math.Min(seconds, 86_400)).Ticks);
        }
    }
}
