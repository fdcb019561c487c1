using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Path instructions (RAPID reference, "StopMove", "StartMove", "ClearPath"): StopMove holds the motion on its path where the arm
/// is, StartMove lets it go on from there, ClearPath (motion task) removes what is left of the motion under way. From a task
/// without motion (the monitor) StopMove and StartMove need \AllMotionTasks, as on the controller.
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
            if (!call.Machine.Task.IsMotionTask)
            {
                throw ArgumentError(call, "ClearPath can only be used in a motion task");
            }
            call.Machine.Task.Controller.Arm.ClearPath();
        }),
    ];

    private static void RequireMotionOrAll(RapidCall call, string name, int all)
    {
        if (!call.Machine.Task.IsMotionTask && !call.Has(all))
        {
            throw ArgumentError(call, $"{name} in a task without motion needs \\AllMotionTasks");
        }
    }
}
