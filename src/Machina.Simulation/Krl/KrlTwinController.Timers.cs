namespace Machina.Simulation.Krl;

/// <summary>
/// The timers: $TIMER[i] counts milliseconds up while $TIMER_STOP[i] is FALSE, and $TIMER_FLAG[i] is TRUE while $TIMER[i] is 0 or
/// more (a program sets a negative value, starts the timer, and an interrupt on the flag fires when the time has passed). They
/// count the time the program lives in: in real-time mode the controller's time source; otherwise the program time (motions,
/// waits, and the interpreter cycles a WAIT FOR spends while a timer runs, see <see cref="WaitForInputs"/>), so that a program
/// sees the same timer values however loaded the machine that verifies it is. The timers are counted when a program reads them,
/// when a timer is started or stopped, and by the submit interpreter each cycle.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>Number of timers ($TIMER[1..64]).</summary>
    public const int TimerCount = 64;

    /// <summary>The interpreter cycle (the KRC's interpolation cycle, 12 ms): how often a WAIT FOR looks again while a timer runs.</summary>
    public static readonly TimeSpan InterpreterCycle = TimeSpan.FromMilliseconds(12);

    private readonly Lock _timerGate = new();
    private readonly bool[] _timerRunning = new bool[TimerCount];
    private long _timersAt = -1;
    private long _timerFraction;
    private volatile bool _timersCounting;

    /// <summary>True while a timer runs: the robot interpreter looks at its interrupts at every statement then.</summary>
    public bool TimersCounting => _timersCounting;

    /// <summary>The timers' time now, in ticks (100 ns): the time source's in real-time mode, the program time otherwise.</summary>
    private long TimerTicks() => Clock.RealTime
        ? Options.Time.GetElapsedTime(0, Options.Time.GetTimestamp()).Ticks
        : (long)Math.Round(Clock.Seconds * TimeSpan.TicksPerSecond);

    /// <summary>
    /// Adds the milliseconds since the last count to every timer that ran since then, then takes which timers run from
    /// $TIMER_STOP (so a timer started or stopped between two counts counts from or to the count made when it changed).
    /// </summary>
    public void CountTimers()
    {
        lock (_timerGate)
        {
            long now = TimerTicks();
            long last = _timersAt;
            _timersAt = now;
            object[] timers = ((KrlArrayValue)Motion.Timer.Box[0]).Objects;
            object[] stopped = ((KrlArrayValue)Motion.TimerStop.Box[0]).Objects;
            if (last >= 0 && now > last)
            {
                // Whole milliseconds; the rest carries over to the next count.
                long elapsed = now - last + _timerFraction;
                long ms = Math.Min(elapsed / TimeSpan.TicksPerMillisecond, int.MaxValue);
                _timerFraction = elapsed - ms * TimeSpan.TicksPerMillisecond;
                for (int i = 0; i < timers.Length; i++)
                {
                    if (_timerRunning[i])
                    {
                        timers[i] = KrlValues.Box((int)Math.Min((int)timers[i] + ms, int.MaxValue));
                    }
                }
            }
            bool any = false;
            for (int i = 0; i < TimerCount; i++)
            {
                _timerRunning[i] = !(bool)stopped[i];
                any |= _timerRunning[i];
            }
            _timersCounting = any;
        }
    }

    /// <summary>$TIMER_FLAG: TRUE for each timer at 0 ms or more (counted first).</summary>
    public KrlArrayValue TimerFlags()
    {
        CountTimers();
        object[] timers = ((KrlArrayValue)Motion.Timer.Box[0]).Objects;
        KrlType type = KrlType.Array(KrlType.Bool, TimerCount);
        var flags = new object[TimerCount];
        for (int i = 0; i < TimerCount; i++)
        {
            flags[i] = KrlValues.Box((int)timers[i] >= 0);
        }
        return new KrlArrayValue(type, flags);
    }
}
