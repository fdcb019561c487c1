namespace Machina.Simulation.Rapid;

/// <summary>
/// Coordinated motion of several robots (MultiMove: SyncMoveOn, SyncMoveOff, SyncMoveUndo, IsSyncMoveOn). The twin has one robot: a
/// program loads, and stops with a clear message when it starts synchronized motion.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> MultiMove() =>
    [
        Instruction("SyncMoveOn", [P("SyncID", "syncident", true), new RapidBuiltinParam("TaskList", "tasks", Ref: true, Rank: 1), Opt("TimeOut", "num")],
            call => throw SingleRobot(call, "SyncMoveOn")),
        Instruction("SyncMoveOff", [P("SyncID", "syncident", true), Opt("TimeOut", "num")], call => throw SingleRobot(call, "SyncMoveOff")),
        Instruction("SyncMoveUndo", [], _ => { }),
        Function("IsSyncMoveOn", "bool", [], _ => false),
    ];

    /// <summary>The task's stop: the twin moves one robot, so synchronized motion of several (MultiMove) cannot run; no handler takes it.</summary>
    private static RapidRuntimeException SingleRobot(RapidCall call, string instruction) =>
        new(RapidErrorNumbers.ByName["ERR_SYNCMOVEON"], call.Line,
            $"{instruction}: the twin moves one robot ({call.Machine.Task.Controller.Options.Model}); synchronized motion of several robots (MultiMove) is not supported")
        { Fatal = true };
}
