namespace Machina.Simulation.Krl;

/// <summary>
/// The program states the system variables report (<see cref="KrlProgramManagement"/>): the robot program's from how its run
/// stands, the submit interpreter's from whether it runs, and the controller's millisecond clock.
/// </summary>
internal sealed partial class KrlTwinController
{
    private int _motionsRunning;

    /// <summary>$PRO_MOVE: true while the robot interpreter runs a motion statement.</summary>
    public bool RunsMotion => Volatile.Read(ref _motionsRunning) > 0;

    /// <summary>The robot interpreter starts (<paramref name="starts"/>) or ends a motion statement.</summary>
    public void MotionRuns(bool starts)
    {
        if (starts)
        {
            Interlocked.Increment(ref _motionsRunning);
        }
        else
        {
            Interlocked.Decrement(ref _motionsRunning);
        }
    }

    /// <summary>$PRO_STATE1: P_ACTIVE while the robot program runs, P_END at its END, P_STOP after a HALT or an error, P_RESET when selected and not started, P_FREE when none is loaded.</summary>
    public string RobotProgramState => State switch
    {
        KrlProgramState.Running => "P_ACTIVE",
        KrlProgramState.Finished => "P_END",
        KrlProgramState.Stopped or KrlProgramState.Failed => "P_STOP",
        _ => MainRoutine is null ? "P_FREE" : "P_RESET",
    };

    /// <summary>$PRO_STATE0: P_ACTIVE while the submit interpreter runs, P_FREE otherwise.</summary>
    public string SubmitProgramState => SubmitsRunning ? "P_ACTIVE" : "P_FREE";

    /// <summary>$ROB_TIMER: the controller's clock in milliseconds (the timers' time: real in real time, the program time otherwise), wrapping as an INT.</summary>
    public int RobotTimerMs() => unchecked((int)(TimerTicks() / TimeSpan.TicksPerMillisecond));
}
