namespace Machina.Simulation.Rapid;

/// <summary>
/// CalcJointT: the joints of a robtarget for a tool and work object, nearest to where the arm is (the model's kinematics). A target
/// the arm cannot reach raises ERR_OUTSIDE_REACH; one it reaches only with an axis beyond its limits, ERR_ROBLIMIT.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Kinematics() =>
    [
        Function("CalcJointT", "jointtarget", [P("Rob_target", "robtarget"), P("Tool", "tooldata"), Opt("WObj", "wobjdata")], call =>
        {
            Twin.TwinArm arm = call.Machine.Task.Controller.Arm;
            Pose wobj = call.Has(2) ? WorkObjectFrame(call, call.Record(2)) : Pose.Identity;
            Pose flange = wobj * RapidGeometry.ToPose(call.Record(0), call.Line) * ToolFrame(call, call.Record(1)).Inverse();
            Joints joints = (flange.Position.IsFinite ? arm.Model.Kinematics.Closest(flange, arm.Joints) : null)
                ?? throw call.Error(RapidErrorNumbers.ByName["ERR_OUTSIDE_REACH"], "CalcJointT: the target is outside the robot's working area");
            try
            {
                arm.RequireWithinLimits(joints);
            }
            catch (Twin.TwinMotionException ex)
            {
                throw call.Error(RapidErrorNumbers.RobLimit, $"CalcJointT: {ex.Message}");
            }
            return RapidGeometry.ToJointTarget(joints);
        }),
    ];
}
