namespace Machina.Simulation.Rapid;

/// <summary>What programs ask of the controller itself: the operating mode (OpMode), booked error numbers (BookErrNo), task labels.</summary>
internal sealed partial class RapidTwinController
{
    private int _bookedErrors = RapidBuiltins.FirstBookedErrorNumber - 1;

    /// <summary>The operating mode OpMode reports: AUTO (default), MANR or MANF (the panel's names, as RWS shows them).</summary>
    public string OperationMode { get; set; } = "AUTO";

    /// <summary>The lock TestAndSet and WaitTestAndSet take, one per controller (every task's semaphores).</summary>
    internal Lock SemaphoreGate { get; } = new();

    private int _cycle = (int)RapidExecutionCycle.Once;

    /// <summary>
    /// The run mode of the NORMAL tasks: Once (single cycle, the default: a program started by our tools runs its main once) or
    /// Forever (continuous: main starts again each time it ends). Static and semistatic tasks run continuously whatever it says.
    /// </summary>
    public RapidExecutionCycle Cycle
    {
        get => (RapidExecutionCycle)Volatile.Read(ref _cycle);
        set => Volatile.Write(ref _cycle, (int)value);
    }

    /// <summary>True when <paramref name="task"/> starts its main again when it ends: a static or semistatic task, or any task in continuous mode.</summary>
    internal bool RunsContinuously(RapidTask task) => !task.IsNormal || Cycle == RapidExecutionCycle.Forever;

    /// <summary>
    /// Runs <paramref name="main"/>; after ExitCycle, and after its end when the task runs continuously, runs it again from its start with
    /// the data as they are (a cycle's end is not a program pointer reset).
    /// </summary>
    private void RunCycles(RapidTask task, RapidRoutine main, CancellationToken cancellation)
    {
        while (true)
        {
            try
            {
                task.Machine.Run(main);
                if (!RunsContinuously(task))
                {
                    return;
                }
            }
            catch (RapidExitCycleException)
            {
            }
            cancellation.ThrowIfCancellationRequested();
            // A main that ends at once would otherwise keep a core busy between two cycles; the controller's scheduler lets others run.
            Thread.Yield();
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
