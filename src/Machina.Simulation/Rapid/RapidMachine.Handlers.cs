namespace Machina.Simulation.Rapid;

/// <summary>Error lists of ERROR handlers and UNDO handlers (RAPID kernel, "Error recovery" and "UNDO").</summary>
internal sealed partial class RapidMachine
{
    /// <summary>True when the ERROR handler of <paramref name="frame"/>'s routine takes error <paramref name="errno"/> (its error list names it, or it has none).</summary>
    private bool Takes(RapidFrame frame, int errno)
    {
        if (frame.Routine.ErrorList is not { } list)
        {
            return true;
        }
        foreach (RapidExpr e in list)
        {
            double listed = (double)Evaluate(e, frame);
            if (listed == errno || listed == RapidErrorNumbers.LongJumpAll)
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>The RETRYs since a retried statement last got past its error (or TRYNEXT, RETURN, ResetRetryCount).</summary>
    private int _retries;

    /// <summary>ResetRetryCount: the retries start again from 0.</summary>
    public void ResetRetries() => _retries = 0;

    /// <summary>
    /// ERR_EXCRTYMAX: one more RETRY than <see cref="RapidTwinOptions.MaxRetries"/> without the statement getting past its error.
    /// RETRY is an instruction of the error handler, so, as any error inside an error handler, it goes to the system error handler:
    /// the task stops with it (<see cref="ToSystemErrorHandler"/>).
    /// </summary>
    private RapidRuntimeException TooManyRetries(RapidRuntimeException error) =>
        new(RapidErrorNumbers.RetryMax, error.Line,
            $"the maximum number of retries ({Task.Controller.Options.MaxRetries}) is exceeded: {error.Reason}")
        { Fatal = true };

    /// <summary>
    /// An error inside an ERROR handler (other than the handled error passed on with RAISE): "it is not possible to recover from or
    /// respond to errors that occur within an error clause. Such errors are always propagated to the system error handler" (RAPID
    /// Reference Manual, Basic Characteristics, "Error Recovery"), which reports it and stops the task: no handler takes it.
    /// </summary>
    private static RapidRuntimeException ToSystemErrorHandler(RapidRuntimeException error) =>
        new(error.ErrorNumber, error.Line, error.Reason) { Event = error.Event, Fatal = true };

    /// <summary>
    /// Runs a routine's body; when an error or ExitCycle leaves it early, its UNDO handler runs first (an error inside the UNDO
    /// handler is dropped: the first one goes on).
    /// </summary>
    private RapidFlow ExecuteUndoable(RapidRoutine routine, RapidFrame frame)
    {
        try
        {
            return ExecuteBlock(routine.Body, frame);
        }
        catch (Exception ex) when (ex is RapidRuntimeException { Fatal: false } or RapidExitCycleException)
        {
            try
            {
                ExecuteBlock(routine.UndoHandler!, frame);
            }
            catch (RapidRuntimeException undoError) when (!undoError.Fatal)
            {
                Task.Controller.Pendant.Log($"{Task.Controller.TaskLabel(Task)}UNDO handler of {routine.Name}: {undoError.Reason} (line {undoError.Line})");
            }
            throw;
        }
    }
}
