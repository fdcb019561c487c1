namespace Machina.Simulation.Krl;

/// <summary>
/// The timers: $TIMER[i] counts milliseconds up on the controller's clock while $TIMER_STOP[i] is FALSE, and $TIMER_FLAG[i] is
/// TRUE while $TIMER[i] is 0 or more (a program sets a negative value, starts the timer, and an interrupt on the flag fires when
/// the time has passed). The timers are counted when a program reads them, when a timer is started or stopped, and by the submit
/// interpreter each cycle.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>Number of timers ($TIMER[1..64]).</summary>
    public const int TimerCount = 64;

    private readonly Lock _timerGate = new();
    private readonly bool[] _timerRunning = new bool[TimerCount];
    private long _timersAt = -1;
    private double _timerFraction;
    private volatile bool _timersCounting;

    /// <summary>True while a timer runs: the robot interpreter looks at its interrupts at every statement then.</summary>
    public bool TimersCounting => _timersCounting;

    /// <summary>
    /// Adds the milliseconds since the last count to every timer that ran since then, then takes which timers run from
    /// $TIMER_STOP (so a timer started or stopped between two counts counts from or to the count made when it changed).
    /// </summary>
    public void CountTimers()
    {
        lock (_timerGate)
        {
            long now = Options.Time.GetTimestamp();
            long last = _timersAt;
            _timersAt = now;
            object[] timers = ((KrlArrayValue)Environment.System["$TIMER"].Box[0]).Items;
            object[] stopped = ((KrlArrayValue)Environment.System["$TIMER_STOP"].Box[0]).Items;
            if (last >= 0)
            {
                // Whole milliseconds; the rest carries over to the next count.
                double elapsed = Options.Time.GetElapsedTime(last, now).TotalMilliseconds + _timerFraction;
                int ms = (int)Math.Min(Math.Floor(elapsed), int.MaxValue);
                _timerFraction = elapsed - ms;
                for (int i = 0; i < timers.Length; i++)
                {
                    if (_timerRunning[i])
                    {
                        timers[i] = KrlValues.Box((int)Math.Min((long)(int)timers[i] + ms, int.MaxValue));
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
        object[] timers = ((KrlArrayValue)Environment.System["$TIMER"].Box[0]).Items;
        KrlType type = KrlType.Array(KrlType.Bool, TimerCount);
        var flags = new object[TimerCount];
        for (int i = 0; i < TimerCount; i++)
        {
            flags[i] = KrlValues.Box((int)timers[i] >= 0);
        }
        return new KrlArrayValue(type, flags);
    }
}
