using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>
    /// The rest of what SDU's ur_rtde control script calls (for the software the twin reports), from UR's Script Manual:
    /// <c>get_actual_tool_flange_pose</c> (the flange, without the TCP), <c>get_tcp_offset</c>, <c>get_target_payload</c> and
    /// <c>get_target_payload_cog</c> (as set), <c>get_target_waypoint</c> (the target of the motion in progress, else where the
    /// TCP is), <c>get_joint_torques</c> (zeros: the torques less those the arm needs to move itself, with nothing pushing it),
    /// <c>get_freedrive_status</c> (0: no singularity near), <c>teach_mode</c>/<c>end_teach_mode</c> (as freedrive: nobody pushes
    /// the arm), <c>enable_external_ft_sensor</c> (checked, as <c>ft_rtde_input_enable</c>), <c>servoc</c> (a linear move to
    /// the pose at v and a: the twin does not blend it on a circle) and <c>protective_stop</c> (the controller's protective stop:
    /// the program waits until it is unlocked and played).
    /// </summary>
    private static void AddRtdeControl(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "get_actual_tool_flange_pose", (m, line, a) => UrGeometry.FromPose(m.Controller.Arm.Model.Kinematics.Forward(m.Controller.JointsNow())));
        Add(t, "get_tcp_offset", (m, line, a) => UrGeometry.FromPose(m.Controller.Arm.ToolCenter));
        Add(t, "get_target_payload", (m, line, a) => m.Controller.Arm.PayloadKg);
        Add(t, "get_target_payload_cog", (m, line, a) => new UrList([.. m.Controller.Modes.PayloadCog.Select(c => (object)c)]));
        Add(t, "get_target_waypoint", (m, line, a) =>
        {
            UrMotion? motion = m.Controller.Motion;
            TwinArm arm = m.Controller.Arm;
            return UrGeometry.FromPose(motion is null ? arm.Tcp : arm.Model.Kinematics.Forward(motion.Target) * arm.ToolCenter);
        });
        Add(t, "get_joint_torques", (m, line, a) => new UrList([0.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
        // The wrench at the tool (Script Manual: p[Fx, Fy, Fz, TRx, TRy, TRz] in the base's axes): no force model, none acts.
        Add(t, "get_tcp_force", (m, line, a) => new UrPose([0.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
        Add(t, "get_freedrive_status", (m, line, a) => 0);
        Add(t, "teach_mode", (m, line, a) =>
        {
            FinishBlend(m, line);
            m.Controller.Modes.Freedrive = true;
            return UrNone.Value;
        });
        Add(t, "end_teach_mode", (m, line, a) =>
        {
            m.Controller.Modes.Freedrive = false;
            return UrNone.Value;
        });
        AddSensorInput(t, "enable_external_ft_sensor");
        Add(t, "servoc", (m, line, a) => MoveLinear(m, line, [a[0], a[1], a[2], 0.0, a[3]], "servoc"), R("pose"), O("a", 1.2), O("v", 0.25), O("r", 0));
        Add(t, "protective_stop", (m, line, a) =>
        {
            FinishBlend(m, line);
            CancellationToken token = m.Cancellation;
            m.Unlocked(() =>
            {
                m.Controller.RequestProtectiveStop();
                m.Controller.WaitWhileHeld(token);
                return 0;
            });
            return UrNone.Value;
        });
    }
}
