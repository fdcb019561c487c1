namespace Machina.Simulation.UrScript;

/// <summary>
/// Secondary programs (the Script Manual's "Secondary Programs"): a program defined with <c>sec</c> and sent to a script port
/// runs beside the main program, which goes on; it "should not use any physical time" (no <c>sleep</c>, no motion: such a
/// program is refused) and an error in it does not stop the main program: it is reported in the controller's log
/// (<see cref="SecondaryErrors"/>), not on the pendant. It runs in one controller step ("Secondary Program Limitations": "Entire
/// execution time is added to single real time cycle"): one that does more than <see cref="UrTwinOptions.SecondaryStepWork"/>
/// (a long or endless loop) stops there with "Runtime is too much behind" and a protective stop.
/// </summary>
internal sealed partial class UrTwinController
{
    private readonly CancellationTokenSource _secondaryStop = new();
    private readonly List<string> _secondaryErrors = [];
    private int _secondaryRuns;

    /// <summary>The errors of secondary programs, in order (the controller's log).</summary>
    public IReadOnlyList<string> SecondaryErrors
    {
        get
        {
            lock (_gate)
            {
                return [.. _secondaryErrors];
            }
        }
    }

    /// <summary>How many secondary programs ran to their end (or their error).</summary>
    public int SecondaryProgramsRun => Volatile.Read(ref _secondaryRuns);

    /// <summary>
    /// Runs the secondary <paramref name="program"/> on a thread of its own beside the main program (its variables its own), or
    /// refuses it when it uses physical time.
    /// </summary>
    private void LaunchSecondary(UrBoundProgram program)
    {
        if (program.PhysicalTimeCall is { } call)
        {
            SecondaryFailed($"line {call.Line}: {call.Name}: a secondary program cannot use physical time (motion, sleep, sync)");
            Interlocked.Increment(ref _secondaryRuns);
            return;
        }
        CancellationToken stop = _secondaryStop.Token;
        new Thread(() => RunSecondary(program, stop)) { IsBackground = true, Name = "URScript secondary program" }.Start();
    }

    private void RunSecondary(UrBoundProgram program, CancellationToken cancellation)
    {
        using var machine = new UrMachine(program, this, cancellation) { StepWork = Options.SecondaryStepWork };
        try
        {
            machine.Run();
        }
        catch (UrRuntimeException e) when (e.Reason.StartsWith(UrMachine.TooMuchBehind, StringComparison.Ordinal))
        {
            // It held the real-time thread past its step ("Secondary Program Limitations": "Runtime is too much behind"): the
            // controller misses its cycle and stops the arm, as for any thread that uses too much time.
            SecondaryFailed(e.Message);
            Pendant.Log($"Protective stop: {UrMachine.TooMuchBehind}");
            RequestProtectiveStop();
        }
        catch (UrRuntimeException e)
        {
            SecondaryFailed(e.Message);
        }
        catch (OperationCanceledException)
        {
        }
        finally
        {
            foreach (UrSocket socket in machine.Sockets.Values)
            {
                socket.Dispose();
            }
            Interlocked.Increment(ref _secondaryRuns);
        }
    }

    /// <summary>Records a secondary program's error in the controller's log.</summary>
    private void SecondaryFailed(string message)
    {
        lock (_gate)
        {
            _secondaryErrors.Add("Secondary program: " + message);
        }
        StateChanged?.Invoke();
    }
}
