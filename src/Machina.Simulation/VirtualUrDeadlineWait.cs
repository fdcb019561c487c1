namespace Machina.Simulation;

/// <summary>
/// The wait of the virtual UR's RTDE sender thread: until a timestamp of the controller's clock, or until woken. On the system
/// clock it sleeps whole milliseconds towards the deadline (to the nearest: a timed wait of n ms ends a little after n ms) and
/// yields the last fraction of a millisecond, so that a 2 ms period is kept to a fraction of a millisecond instead of the one to
/// two milliseconds a <c>Task.Delay</c> per tick adds (issue 45: 500 Hz asked gave 248 Hz). On any other clock (a test's manual
/// clock) it waits for a timer of that clock, rounded up to whole milliseconds (<see cref="VirtualUrController.WholeMillisecondsUp"/>).
/// Nothing to dispose: the event is never asked for its wait handle, so it holds no operating-system object.
/// </summary>
internal sealed class VirtualUrDeadlineWait(TimeProvider clock)
{
    private readonly ManualResetEventSlim _event = new(false, 1);
    private readonly bool _systemClock = ReferenceEquals(clock, TimeProvider.System);
    private int _woken;

    /// <summary>Ends the current or next wait at once (a change to report).</summary>
    public void Wake()
    {
        Volatile.Write(ref _woken, 1);
        _event.Set();
    }

    /// <summary>
    /// Waits until <paramref name="deadline"/> (a timestamp of the clock) or a <see cref="Wake"/>; true when woken. Throws
    /// <see cref="OperationCanceledException"/> when <paramref name="token"/> is cancelled.
    /// </summary>
    public bool WaitUntil(long deadline, CancellationToken token)
    {
        var spin = default(SpinWait);
        while (true)
        {
            token.ThrowIfCancellationRequested();
            _event.Reset(); // before looking at the flag: a Wake after this look sets the event again, and the wait below ends
            if (Interlocked.Exchange(ref _woken, 0) == 1)
            {
                return true;
            }
            long now = clock.GetTimestamp();
            TimeSpan left = clock.GetElapsedTime(now, deadline);
            if (left <= TimeSpan.Zero)
            {
                return false;
            }
            double ms = Math.Round(left.TotalMilliseconds);
            if (!_systemClock)
            {
                using ITimer timer = clock.CreateTimer(static e => ((ManualResetEventSlim)e!).Set(), _event, VirtualUrController.WholeMillisecondsUp(left), Timeout.InfiniteTimeSpan);
                if (clock.GetTimestamp() == now)
                {
                    _event.Wait(token); // else the clock moved while the timer was made (it would be late): look again
                }
            }
            else if (ms >= 1)
            {
                _event.Wait((int)Math.Min(ms, int.MaxValue), token);
            }
            else
            {
                spin.SpinOnce(sleep1Threshold: -1); // under half a millisecond left: yield, never sleep a whole one
            }
        }
    }
}
