using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// The submit interpreter: a second KRL program that runs beside the robot program, cyclically (as sps.sub's loop calls the
/// user's PLC routines); it counts the timers (see KrlTwinController.Timers.cs) before each cycle.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>
    /// Calls <paramref name="routine"/> (a subprogram without parameters) once every <paramref name="cycle"/> of the wall clock
    /// until <paramref name="cancellation"/>, counting the timers up before each call. The cycle is the controller's, not the
    /// robot's: a twin running faster than real time runs its submit interpreter no more often (at 1000× a cycle of the scaled
    /// clock was 4 µs, and the monitor it calls sent a report in nearly every one), as a RAPID background task's waits are on
    /// the wall clock. Between two cycles the thread sleeps in the kernel; so it does after each turn of a LOOP (a submit program
    /// such as sps.sub loops on its own: one turn per cycle). An error stops the submit interpreter with the controller's message
    /// in the logbook; the robot program runs on.
    /// </summary>
    public void RunSubmit(string routine, TimeSpan cycle, CancellationToken cancellation)
    {
        KrlRoutine? found = KrlBinder.FindRoutine(_modules, null, routine);
        if (found is null || found.Parameters.Count > 0 || found.ReturnType is not null)
        {
            Pendant.Log($"Submit interpreter: program {routine} not found");
            return;
        }
        var sleep = new TwinSleep();
        TimeProvider wall = TwinScaledTime.Wall(Options.Time);
        var line = new KrlRunningLine();
        var machine = new KrlMachine(this, cancellation) { LoopTurnWait = token => sleep.Wait(wall, cycle, token), TracedLine = line };
        using SubmitThread thread = EnterSubmitThread(line);
        try
        {
            while (!cancellation.IsCancellationRequested)
            {
                CountTimers();
                machine.Run(found);
                sleep.Wait(wall, cycle, cancellation);
            }
        }
        catch (KrlRuntimeException ex)
        {
            Pendant.Log(FormattableString.Invariant($"Submit interpreter stopped: {ex.Message} ({ex.File ?? machine.File}, line {(ex.Line > 0 ? ex.Line : machine.Line)})"));
        }
        catch (KrlHaltException)
        {
            Pendant.Log("Submit interpreter stopped: HALT");
        }
        catch (OperationCanceledException)
        {
            // The controller stops.
        }
    }
}
