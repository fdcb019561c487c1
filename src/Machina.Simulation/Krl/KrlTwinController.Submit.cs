namespace Machina.Simulation.Krl;

/// <summary>
/// The submit interpreter: a second KRL program that runs beside the robot program, cyclically (as sps.sub's loop calls the
/// user's PLC routines), and the timers ($TIMER) that count up on the controller's clock while not stopped ($TIMER_STOP).
/// </summary>
internal sealed partial class KrlTwinController
{
    private long _timersAt = -1;
    private double _timerFraction;

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
        try
        {
            while (!cancellation.IsCancellationRequested)
            {
                CountTimers();
                machine.Run(found);
                Task.Delay(cycle, Options.Time, cancellation).GetAwaiter().GetResult();
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

    /// <summary>Adds the milliseconds since the last count to every running timer ($TIMER_STOP[i] FALSE).</summary>
    public void CountTimers()
    {
        long now = Options.Time.GetTimestamp();
        long last = Interlocked.Exchange(ref _timersAt, now);
        if (last < 0)
        {
            return;
        }
        // Whole milliseconds; the rest carries over to the next count.
        double elapsed = Options.Time.GetElapsedTime(last, now).TotalMilliseconds + _timerFraction;
        int ms = (int)Math.Min(Math.Floor(elapsed), int.MaxValue);
        _timerFraction = elapsed - ms;
        object[] timers = ((KrlArrayValue)Environment.System["$TIMER"].Value).Items;
        object[] stopped = ((KrlArrayValue)Environment.System["$TIMER_STOP"].Value).Items;
        for (int i = 0; i < timers.Length; i++)
        {
            if (!(bool)stopped[i])
            {
                timers[i] = KrlValues.Box((int)Math.Min((long)(int)timers[i] + ms, int.MaxValue));
            }
        }
    }
}
