using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Path instructions (RAPID reference, "StopMove", "StartMove", "ClearPath"): StopMove holds the motion on its path where the arm
/// is, StartMove lets it go on from there, ClearPath (motion task) removes what is left of the motion under way. From a task
/// without motion (the monitor) StopMove and StartMove need \AllMotionTasks, as on the controller. StorePath keeps the motion of
/// the path level as it was (held, cleared) and lets a trap or error handler move on a new level; RestoPath gives that motion back
/// (StartMove then goes on with it, a cleared one stays cleared). One path at a time.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Path() =>
    [
        Instruction("StopMove", [Sw("Quick"), Sw("AllMotionTasks")], call =>
        {
            RequireMotionOrAll(call, "StopMove", 1);
            call.Machine.Task.Controller.Arm.Hold();
            call.Machine.Task.Controller.Arm.Record(call.Line, TwinTraceKind.Wait, "StopMove");
        }),
        Instruction("StartMove", [Sw("AllMotionTasks")], call =>
        {
            RequireMotionOrAll(call, "StartMove", 0);
            call.Machine.Task.Controller.Arm.Release();
        }),
        Instruction("ClearPath", [], call =>
        {
            RequireMotion(call, "ClearPath");
            call.Machine.Task.Controller.Arm.ClearPath();
            call.Machine.Task.PathCleared = true;
        }),
        Instruction("StorePath", [Sw("KeepSync")], call =>
        {
            RapidTask task = call.Machine.Task;
            RequireMotion(call, "StorePath");
            if (task.StoredPath is not null)
            {
                throw ArgumentError(call, "StorePath: a path is already stored (one at a time; RestoPath first)");
            }
            // The motion of the stored level stays as it was (held, cleared); the new level may move.
            TwinArm arm = task.Controller.Arm;
            task.StoredPath = (arm.IsHeld, task.PathCleared);
            task.PathCleared = false;
            arm.Release();
        }),
        Instruction("RestoPath", [], call =>
        {
            RapidTask task = call.Machine.Task;
            RequireMotion(call, "RestoPath");
            if (task.StoredPath is not (bool held, bool cleared))
            {
                throw ArgumentError(call, "RestoPath: no path is stored (StorePath first)");
            }
            task.StoredPath = null;
            TwinArm arm = task.Controller.Arm;
            arm.FinishBlend(task.CancellationToken);
            arm.Hold();
            if (cleared)
            {
                arm.ClearPath(); // the motion that was cleared before StorePath stays cleared
            }
            if (!held)
            {
                arm.Release();
            }
            task.PathCleared = cleared;
        }),
    ];

    private static void RequireMotion(RapidCall call, string name)
    {
        if (!call.Machine.Task.IsMotionTask)
        {
            throw ArgumentError(call, $"{name} can only be used in a motion task");
        }
    }

    private static void RequireMotionOrAll(RapidCall call, string name, int all)
    {
        if (!call.Machine.Task.IsMotionTask && !call.Has(all))
        {
            throw ArgumentError(call, $"{name} in a task without motion needs \\AllMotionTasks");
        }
    }
}
