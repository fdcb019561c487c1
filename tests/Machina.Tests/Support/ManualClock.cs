namespace Machina.Tests.Support;

/// <summary>
/// A clock that only moves when a test calls <see cref="Advance"/>: delays and timers built on it fire then, on the
/// calling thread, in time order. It makes motion, monitor and timeout tests independent of machine speed.
/// </summary>
internal sealed class ManualClock : TimeProvider
{
    private static readonly DateTimeOffset Epoch = new(2026, 1, 1, 0, 0, 0, TimeSpan.Zero);

    private readonly object _gate = new();
    private readonly List<ManualTimer> _timers = [];
    private long _now;
    private int _timersCreated;

    /// <summary>Clock ticks are <see cref="TimeSpan"/> ticks.</summary>
    public override long TimestampFrequency => TimeSpan.TicksPerSecond;

    /// <summary>How many timers (delays, timeouts) have been made on this clock so far.</summary>
    internal int TimersCreated => Volatile.Read(ref _timersCreated);

    /// <summary>Time since the clock was made.</summary>
    internal TimeSpan Elapsed => TimeSpan.FromTicks(GetTimestamp());

    public override long GetTimestamp()
    {
        lock (_gate)
        {
            return _now;
        }
    }

    public override DateTimeOffset GetUtcNow() => Epoch + Elapsed;

    public override ITimer CreateTimer(TimerCallback callback, object? state, TimeSpan dueTime, TimeSpan period)
    {
        Interlocked.Increment(ref _timersCreated);
        var timer = new ManualTimer(this, callback, state);
        timer.Change(dueTime, period);
        return timer;
    }

    /// <summary>How many timers are set and have not fired (or been stopped) yet.</summary>
    internal int PendingTimers
    {
        get
        {
            lock (_gate)
            {
                return _timers.Count;
            }
        }
    }

    /// <summary>True when some timer is set to fire exactly <paramref name="dueIn"/> from now.</summary>
    internal bool HasTimerDueIn(TimeSpan dueIn)
    {
        lock (_gate)
        {
            return _timers.Any(t => t.DueAt == _now + dueIn.Ticks);
        }
    }

    /// <summary>
    /// Moves the clock to the earliest pending timer and fires the timers due then, and no later ones: a timer that a woken
    /// thread sets meanwhile is due after now, so it waits for the next call (with <see cref="Advance"/> past a timer, a
    /// thread woken quickly enough could set its next timer inside the span and see it fire at once). Returns how far the
    /// clock moved, or null when no timer is pending.
    /// </summary>
    internal TimeSpan? AdvanceToNextTimer()
    {
        long by;
        lock (_gate)
        {
            if (_timers.Count == 0)
            {
                return null;
            }
            by = _timers.Min(t => t.DueAt) - _now;
        }
        Advance(TimeSpan.FromTicks(by));
        return TimeSpan.FromTicks(by);
    }

    /// <summary>Moves the clock forward, firing every timer that falls due on the way, earliest first.</summary>
    internal void Advance(TimeSpan by)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(by, TimeSpan.Zero);
        long target;
        lock (_gate)
        {
            target = _now + by.Ticks;
        }
        while (true)
        {
            ManualTimer? next;
            lock (_gate)
            {
                next = _timers.Where(t => t.DueAt <= target).MinBy(t => t.DueAt);
                if (next is null)
                {
                    _now = target;
                    return;
                }
                _now = Math.Max(_now, next.DueAt);
                if (next.PeriodTicks > 0)
                {
                    next.DueAt += next.PeriodTicks;
                }
                else
                {
                    _timers.Remove(next);
                }
            }
            next.Fire();
        }
    }

    /// <summary>
    /// From now until the result is disposed, the clock follows real time (checked every 10 ms): what a test no longer needs
    /// to hold still (a reconnection after the part it checks) gets its timeouts as on a real clock, never a wait that cannot end.
    /// </summary>
    internal IAsyncDisposable RunFreely()
    {
        var stop = new CancellationTokenSource();
        Task running = Task.Run(async () =>
        {
            long last = TimeProvider.System.GetTimestamp();
            while (!stop.IsCancellationRequested)
            {
                try
                {
                    await Task.Delay(10, stop.Token).ConfigureAwait(false);
                }
                catch (OperationCanceledException)
                {
                    return;
                }
                long now = TimeProvider.System.GetTimestamp();
                Advance(TimeProvider.System.GetElapsedTime(last, now));
                last = now;
            }
        });
        return new FreeRun(stop, running);
    }

    private sealed class FreeRun(CancellationTokenSource stop, Task running) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            await stop.CancelAsync().ConfigureAwait(false);
            await running.ConfigureAwait(false);
            stop.Dispose();
        }
    }

    private void Schedule(ManualTimer timer, TimeSpan dueTime, TimeSpan period)
    {
        lock (_gate)
        {
            _timers.Remove(timer);
            if (dueTime == Timeout.InfiniteTimeSpan)
            {
                return;
            }
            timer.DueAt = _now + Math.Max(0, dueTime.Ticks);
            timer.PeriodTicks = period == Timeout.InfiniteTimeSpan ? 0 : Math.Max(1, period.Ticks);
            _timers.Add(timer);
        }
    }

    private sealed class ManualTimer(ManualClock clock, TimerCallback callback, object? state) : ITimer
    {
        internal long DueAt { get; set; }

        internal long PeriodTicks { get; set; }

        internal void Fire() => callback(state);

        public bool Change(TimeSpan dueTime, TimeSpan period)
        {
            clock.Schedule(this, dueTime, period);
            return true;
        }

        public void Dispose() => clock.Schedule(this, Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);

        public ValueTask DisposeAsync()
        {
            Dispose();
            return ValueTask.CompletedTask;
        }
    }
}
