namespace Machina.Simulation;

/// <summary>
/// The wait of the virtual UR's RTDE sender thread: until a timestamp of the controller's clock, or until woken. On the system
/// clock on Linux it waits whole milliseconds on an event while more than <see cref="FinalStretch"/> is left (a wake ends
/// it at once), then sleeps the rest to the microsecond (<see cref="VirtualUrRtdeSleep"/>) and ends at the deadline: a package
/// leaves on its deadline instead of up to half a millisecond either side of it, and a wake that comes in the last stretch is
/// answered at the deadline (at most <see cref="FinalStretch"/> later, the next package of a 500 Hz client anyway). On the
/// system clock elsewhere it sleeps whole milliseconds towards the deadline, to the nearest (a timed wait of n ms ends a little
/// after n ms), and ends once less than <see cref="Early"/> is left: the sender sends a package due within that much at once
/// (<see cref="VirtualUrController"/>'s subscribers count it due), on the grid of its deadlines. It never spins or yields the
/// processor for the last fraction of a millisecond: on a loaded machine a yield gives the core to every other runnable thread
/// for a slice each, and the package left several milliseconds late (issue 45: p99 period error 5.7 ms at a load of 8.6). On
/// any other clock (a test's manual clock) it waits for a timer of that clock, rounded up to whole milliseconds
/// (<see cref="VirtualUrController.WholeMillisecondsUp"/>), and ends only at the deadline. Nothing to dispose: the event is
/// never asked for its wait handle, so it holds no operating-system object.
/// </summary>
internal sealed class VirtualUrDeadlineWait(TimeProvider clock)
{
    private readonly ManualResetEventSlim _event = new(false, 1);
    private int _woken;

    private readonly bool _system = ReferenceEquals(clock, TimeProvider.System);
    /// <summary>Decided once (a sleep of nothing tells whether the C library has it): the subscribers count with <see cref="Early"/>.</summary>
    private readonly bool _precise = ReferenceEquals(clock, TimeProvider.System) && VirtualUrRtdeSleep.Available && VirtualUrRtdeSleep.Sleep(0);

    /// <summary>The part of a wait slept to the microsecond (when <see cref="Precise"/>), not interrupted by a wake.</summary>
    public static readonly TimeSpan FinalStretch = TimeSpan.FromMilliseconds(2.5);

    /// <summary>True while the wait ends at the deadline to the microsecond (the system clock on Linux).</summary>
    public bool Precise => _precise;

    /// <summary>
    /// How early a deadline counts as reached: half a millisecond on the system clock when the wait counts whole milliseconds,
    /// none when it is <see cref="Precise"/> or on any other clock.
    /// </summary>
    public TimeSpan Early => _system && !_precise ? TimeSpan.FromMilliseconds(0.5) : TimeSpan.Zero;

    /// <summary>
    /// Called on the thread that will wait: asks for its timer slack of a microsecond and a short time slice
    /// (<see cref="VirtualUrRtdeSlice"/>: woken at a deadline, it takes a busy core at once) when the wait is <see cref="Precise"/>.
    /// </summary>
    public void OnWaitingThread()
    {
        if (_precise)
        {
            VirtualUrRtdeSleep.TightenTimerSlack();
            VirtualUrRtdeSlice.Shorten();
        }
    }

    /// <summary>Ends the current or next wait at once (a change to report).</summary>
    public void Wake()
    {
        Volatile.Write(ref _woken, 1);
        _event.Set();
    }

    /// <summary>
    /// Takes a wake that came before the waiting thread looks at what it serves (true when there was one): that look serves it,
    /// and a later <see cref="WaitUntil"/> must not end at once for it (the RTDE sender would send a second package of the tick).
    /// </summary>
    public bool TakeWake() => Interlocked.Exchange(ref _woken, 0) == 1;

    /// <summary>
    /// Waits until <see cref="Early"/> before <paramref name="deadline"/> (a timestamp of the clock) or a <see cref="Wake"/>;
    /// true when woken. Throws <see cref="OperationCanceledException"/> when <paramref name="token"/> is cancelled.
    /// </summary>
    public bool WaitUntil(long deadline, CancellationToken token)
    {
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
            if (left <= Early)
            {
                return false;
            }
            if (_precise)
            {
                if (left > FinalStretch)
                {
                    // Whole milliseconds on the event (a wake ends them), leaving between FinalStretch - 1 ms and FinalStretch.
                    _event.Wait((int)Math.Min(Math.Ceiling((left - FinalStretch).TotalMilliseconds), int.MaxValue), token);
                }
                else
                {
                    VirtualUrRtdeSleep.Sleep(left.Ticks * 100); // TimeSpan ticks are 100 ns
                }
                continue;
            }
            if (!_system)
            {
                using ITimer timer = clock.CreateTimer(static e => ((ManualResetEventSlim)e!).Set(), _event, VirtualUrController.WholeMillisecondsUp(left), Timeout.InfiniteTimeSpan);
                if (clock.GetTimestamp() == now)
                {
                    _event.Wait(token); // else the clock moved while the timer was made (it would be late): look again
                }
            }
            else
            {
                // More than half a millisecond left: at least one, and to the nearest, so the wait ends within half of one.
                _event.Wait((int)Math.Min(Math.Max(1, Math.Round(left.TotalMilliseconds, MidpointRounding.AwayFromZero)), int.MaxValue), token);
            }
        }
    }
}
