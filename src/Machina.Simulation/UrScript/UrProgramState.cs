namespace Machina.Simulation.UrScript;

/// <summary>Where the controller's program is.</summary>
internal enum UrProgramState
{
    /// <summary>No program has run yet.</summary>
    Idle,

    /// <summary>A program is running.</summary>
    Running,

    /// <summary>The program ran to its end (or halted).</summary>
    Finished,

    /// <summary>The program was stopped: a new program replaced it, or the controller was stopped.</summary>
    Stopped,

    /// <summary>The program was refused (compile error) or stopped by a runtime error; see the controller's <c>Error</c>.</summary>
    Failed,
}
