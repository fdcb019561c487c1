namespace Machina.Simulation.Rapid;

/// <summary>What programs ask of the controller itself: the operating mode (OpMode), booked error numbers (BookErrNo), task labels.</summary>
internal sealed partial class RapidTwinController
{
    private int _bookedErrors = RapidBuiltins.FirstBookedErrorNumber - 1;

    /// <summary>The operating mode OpMode reports: AUTO (default), MANR or MANF (the panel's names, as RWS shows them).</summary>
    public string OperationMode { get; set; } = "AUTO";

    /// <summary>The lock TestAndSet and WaitTestAndSet take, one per controller (every task's semaphores).</summary>
    internal Lock SemaphoreGate { get; } = new();

    /// <summary>Runs <paramref name="main"/>; after ExitCycle, runs it again from its start with the data as they are.</summary>
    private static void RunCycles(RapidTask task, RapidRoutine main, CancellationToken cancellation)
    {
        while (true)
        {
            try
            {
                task.Machine.Run(main);
                return;
            }
            catch (RapidExitCycleException)
            {
                cancellation.ThrowIfCancellationRequested();
            }
        }
    }

    /// <summary>BookErrNo: the next free number for a program's own error.</summary>
    internal int BookErrorNumber() => Interlocked.Increment(ref _bookedErrors);

    /// <summary>
    /// The prefix of a task's pendant lines when the controller runs more than the motion task ("[T_MONITOR] "), so that each
    /// line says which task wrote it; empty with the motion task alone.
    /// </summary>
    internal string TaskLabel(RapidTask task) => LabelsTasks ? $"[{task.Name}] " : "";

    /// <summary>True when pendant lines and errors carry their task's name (set by a host running several tasks).</summary>
    public bool LabelsTasks { get; set; }
}
