using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// Timer interrupts during a motion in real time: while a motion runs with interrupts switched on, the motion is woken when the
/// soonest running timer reaches 0 ms (its $TIMER_FLAG rises), so that an interrupt on the flag runs at that moment of the
/// motion, as on the controller, rather than when the motion ends. The motion goes on unless the routine brakes and resumes.
/// Outside real time the arm asks for the same moment in program time (<see cref="ProgramTimeWake"/>).
/// </summary>
internal sealed partial class KrlMachine
{
    private ITimer? _timerWake;

    /// <summary>
    /// Sets the wake of the motion under way to the moment the soonest running negative timer reaches 0 (none when no interrupt
    /// is on, no timer runs towards 0, or the twin does not run in real time: there a motion is one step of program time).
    /// </summary>
    private void ArmTimerWake()
    {
        int soonest = _interruptsOn > 0 && Controller.Clock.RealTime ? SoonestTimerMs() : -1;
        if (soonest < 0)
        {
            _timerWake?.Change(Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
            return;
        }
        // At least a millisecond: the timers count whole milliseconds, so a wake a fraction early looks again a millisecond later.
        TimeSpan due = TimeSpan.FromMilliseconds(Math.Max(soonest, 1));
        if (_timerWake is null)
        {
            // On the timer's thread: the arm's motion wakes, and the robot interpreter serves its interrupts (ServeInterrupts).
            _timerWake = Controller.Options.Time.CreateTimer(static arm => ((TwinArm)arm!).Wake(), Controller.Arm, due, Timeout.InfiniteTimeSpan);
        }
        else
        {
            _timerWake.Change(due, Timeout.InfiniteTimeSpan);
        }
    }

    /// <summary>
    /// Outside real time, the program time in seconds until the soonest running timer below 0 reaches 0, when an interrupt is on
    /// and none is being served; negative for none. The arm stops its motion at that moment of the program time, so that the
    /// timer's interrupt runs with the arm part-way (<see cref="TwinArm.NextWake"/>), as it does in real time.
    /// </summary>
    public double ProgramTimeWake()
    {
        // No timer runs (the usual case, e.g. a streaming driver): no wake, without counting the timers for every motion.
        int soonest = _interruptsOn > 0 && !_inInterrupt && Controller.TimersCounting ? SoonestTimerMs() : -1;
        return soonest < 0 ? -1 : soonest / 1000.0;
    }

    /// <summary>Ends the motion's timer wake (the motion has ended).</summary>
    private void DisarmTimerWake()
    {
        _timerWake?.Dispose();
        _timerWake = null;
    }

    /// <summary>Milliseconds until the soonest running timer below 0 reaches 0 (counted now), or -1 when none runs towards 0.</summary>
    private int SoonestTimerMs()
    {
        // Through the cells found once: two case-insensitive look-ups by name at every motion while the monitor's timer runs.
        object[] timers = ((KrlArrayValue)Controller.Motion.Timer.Box[0]).Objects;
        object[] stopped = ((KrlArrayValue)Controller.Motion.TimerStop.Box[0]).Objects;
        if (!AnyRunsBelowZero(timers, stopped))
        {
            // Counting only adds time to running timers: none below 0 now, none after (the monitor's timer counts up from 0 all
            // stream long, and this ran at every motion).
            return -1;
        }
        Controller.CountTimers();
        if (!Controller.TimersCounting)
        {
            return -1;
        }
        int soonest = -1;
        for (int i = 0; i < timers.Length; i++)
        {
            if (!(bool)stopped[i] && (int)timers[i] < 0 && (soonest < 0 || -(int)timers[i] < soonest))
            {
                soonest = -(int)timers[i];
            }
        }
        return soonest;
    }

    /// <summary>True when a timer that is not stopped is below 0 (before counting).</summary>
    private static bool AnyRunsBelowZero(object[] timers, object[] stopped)
    {
        for (int i = 0; i < timers.Length; i++)
        {
            if (!(bool)stopped[i] && (int)timers[i] < 0)
            {
                return true;
            }
        }
        return false;
    }
}
