namespace Machina.Simulation.Krl;

/// <summary>How a KRL program run ended (or that it runs).</summary>
internal enum KrlProgramState
{
    /// <summary>Not started.</summary>
    Idle,

    /// <summary>The robot interpreter is running it.</summary>
    Running,

    /// <summary>It reached the END of its main routine.</summary>
    Finished,

    /// <summary>It stopped at a HALT or was cancelled.</summary>
    Stopped,

    /// <summary>An error stopped it (a motion the robot cannot make, an array index…): see the controller's error.</summary>
    Failed,
}
