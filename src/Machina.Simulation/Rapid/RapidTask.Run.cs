using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>How a task's program runs: its state, the error that stopped it, and whether it is the motion task.</summary>
internal sealed partial class RapidTask
{
    private readonly TwinProgramStatus<RapidProgramState> _status = new();

    /// <summary>True for the motion task (T_ROB1): its motion and waits make the program time.</summary>
    public bool IsMotionTask => Name.Equals(RapidTwinController.MotionTask, StringComparison.OrdinalIgnoreCase);

    /// <summary>The task's Type in the system parameters (NORMAL unless the cell's configuration says otherwise).</summary>
    public RapidTaskType Type { get; set; } = RapidTaskType.Normal;

    /// <summary>True for a NORMAL task: the program's start and stop and the run mode are for it (a static task runs on).</summary>
    public bool IsNormal => Type == RapidTaskType.Normal;

    /// <summary>How the task's last run ended (Running while it runs).</summary>
    public RapidProgramState State => _status.State;

    /// <summary>The event-log message of the error that stopped the task's last run, or null.</summary>
    public string? Error => _status.Error;

    /// <summary>Records how the run ended (or that it runs); <paramref name="meanwhile"/> runs in the same step (nobody sees the state between).</summary>
    /// <remarks>A run that ends first writes what its socket sends hold: whoever sees it ended also got what it sent.</remarks>
    internal void SetState(RapidProgramState state, string? error, Action? meanwhile = null)
    {
        if (state != RapidProgramState.Running)
        {
            Sends.Flush();
            Sends.Disown();
        }
        _status.Set(state, error, meanwhile);
    }
}
