namespace Machina.Simulation.Rapid;

/// <summary>
/// The system parameter Type of a task (topic Controller, type Task): NORMAL tasks run as the controller's run mode says (one cycle
/// or continuous); a STATIC or SEMISTATIC task runs its main for ever, started again when it ends, until an error stops it (RAPID
/// Reference Manual, Basic Characteristics, "Multitasking"; docs/simulation.md).
/// </summary>
internal enum RapidTaskType
{
    /// <summary>NORMAL: started and stopped with the program; its main runs once per start in single-cycle mode.</summary>
    Normal,

    /// <summary>STATIC: a background task that runs for ever (after a power failure it goes on where it was).</summary>
    Static,

    /// <summary>SEMISTATIC: a background task that runs for ever (after a power failure it starts again from the beginning).</summary>
    SemiStatic,
}

/// <summary>The controller's run mode for NORMAL tasks: single cycle (main once) or continuous (main again each time it ends).</summary>
internal enum RapidExecutionCycle
{
    /// <summary>Single cycle: each normal task runs its main once and stops.</summary>
    Once,

    /// <summary>Continuous: each normal task starts its main again each time it ends.</summary>
    Forever,
}
