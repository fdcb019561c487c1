using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// The submit interpreter: a second KRL program that runs beside the robot program, cyclically (as sps.sub's loop calls the
/// user's PLC routines); it counts the timers (see KrlTwinController.Timers.cs) before each cycle.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>
    /// Calls <paramref name="routine"/> (a subprogram without parameters) once every <paramref name="cycle"/> of the controller's
    /// time until <paramref name="cancellation"/>, counting the timers up before each call. An error stops the submit interpreter
    /// with the controller's message in the logbook; the robot program runs on.
    /// </summary>
    public void RunSubmit(string routine, TimeSpan cycle, CancellationToken cancellation)
    {
        KrlRoutine? found = KrlBinder.FindRoutine(_modules, null, routine);
        if (found is null || found.Parameters.Count > 0 || found.ReturnType is not null)
        {
            Pendant.Log($"Submit interpreter: program {routine} not found");
            return;
        }
        var machine = new KrlMachine(this, cancellation);
        using SubmitRun running = SubmitRunning();
        try
        {
            while (!cancellation.IsCancellationRequested)
            {
                CountTimers();
                machine.Run(found);
                TwinWait.Delay(cycle, Options.Time, cancellation);
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
