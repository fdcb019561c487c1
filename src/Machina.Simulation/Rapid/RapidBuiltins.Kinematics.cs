namespace Machina.Simulation.Rapid;

/// <summary>CalcJointT: the joints of a robtarget for a tool and work object, nearest to where the arm is (the model's kinematics).</summary>
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
                ?? throw call.Error(RapidErrorNumbers.RobLimit, "CalcJointT: the target is out of reach");
            return RapidGeometry.ToJointTarget(joints);
        }),
    ];
}
