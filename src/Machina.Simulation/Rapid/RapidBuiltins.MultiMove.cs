namespace Machina.Simulation.Rapid;

/// <summary>
/// Coordinated motion of several robots (MultiMove: SyncMoveOn, SyncMoveOff, SyncMoveUndo, IsSyncMoveOn). The twin has one robot: a
/// program loads, and stops with a clear message when it starts synchronized motion. WaitSyncTask (Multitasking) synchronizes the
/// loaded tasks: each waits until every task of its list reached the sync point of the same name.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> MultiMove() =>
    [
        Instruction("SyncMoveOn", [P("SyncID", "syncident", true), new RapidBuiltinParam("TaskList", "tasks", Ref: true, Rank: 1), Opt("TimeOut", "num")],
            call => throw SingleRobot(call, "SyncMoveOn")),
        Instruction("SyncMoveOff", [P("SyncID", "syncident", true), Opt("TimeOut", "num")], call => throw SingleRobot(call, "SyncMoveOff")),
        Instruction("WaitSyncTask", [Sw("InPos"), P("SyncID", "syncident", true), new RapidBuiltinParam("TaskList", "tasks", Ref: true, Rank: 1), Opt("TimeOut", "num")],
            call =>
            {
                RapidTask task = call.Machine.Task;
                RapidTwinController c = task.Controller;
                string[] tasks = [.. ((RapidArray)call.Value(2)).Items.Select(t => (string)((RapidRecord)t).Fields[0])];
                if (tasks.FirstOrDefault(name => !c.HasTask(name)) is { } missing)
                {
                    throw ArgumentError(call, $"WaitSyncTask: the task list names '{missing}', which is not loaded");
                }
                if (!tasks.Contains(task.Name, StringComparer.OrdinalIgnoreCase))
                {
                    throw ArgumentError(call, $"WaitSyncTask: the task list does not name this task ({task.Name})");
                }
                if (call.Has(0) && task.IsMotionTask)
                {
                    c.Arm.FinishBlend(task.CancellationToken); // \InPos: the robot stands still first
                }
                string id = call.DataName(1) ?? throw ArgumentError(call, "WaitSyncTask: the SyncID must be a syncident variable");
                if (!c.WaitSync(id, task, tasks, call.Has(3) ? call.Num(3) : null))
                {
                    throw call.Error(RapidErrorNumbers.ByName["ERR_WAITSYNCTASK"], $"WaitSyncTask: the other tasks did not reach {id} within \\TimeOut");
                }
            }),
        Instruction("SyncMoveUndo", [], _ => { }),
        Function("IsSyncMoveOn", "bool", [], _ => false),
    ];

    /// <summary>The task's stop: the twin moves one robot, so synchronized motion of several (MultiMove) cannot run; no handler takes it.</summary>
    private static RapidRuntimeException SingleRobot(RapidCall call, string instruction) =>
        new(RapidErrorNumbers.ByName["ERR_SYNCMOVEON"], call.Line,
            $"{instruction}: the twin moves one robot ({call.Machine.Task.Controller.Options.Model}); synchronized motion of several robots (MultiMove) is not supported")
        { Fatal = true };
}
