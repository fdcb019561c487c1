namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    private static void AddPoseMath(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "pose_trans", (m, line, a) => UrGeometry.FromPose(P(a, 0, line, "pose_trans") * P(a, 1, line, "pose_trans")), R("p_from"), R("p_from_to"));
        Add(t, "pose_inv", (m, line, a) => UrGeometry.FromPose(P(a, 0, line, "pose_inv").Inverse()), R("p_from"));
        Add(t, "pose_add", (m, line, a) =>
        {
            Pose p1 = P(a, 0, line, "pose_add"), p2 = P(a, 1, line, "pose_add");
            return UrGeometry.FromPose(new Pose(p1.Position + p2.Position, p2.Rotation * p1.Rotation));
        }, R("p_1"), R("p_2"));
        Add(t, "pose_sub", (m, line, a) =>
        {
            Pose p1 = P(a, 0, line, "pose_sub"), p2 = P(a, 1, line, "pose_sub");
            return UrGeometry.FromPose(new Pose(p1.Position - p2.Position, p1.Rotation * p2.Rotation.Inverse()));
        }, R("p_to"), R("p_from"));
        Add(t, "pose_dist", (m, line, a) => (P(a, 0, line, "pose_dist").Position - P(a, 1, line, "pose_dist").Position).Length / 1000, R("p_from"), R("p_to"));
        Add(t, "point_dist", (m, line, a) => (P(a, 0, line, "point_dist").Position - P(a, 1, line, "point_dist").Position).Length / 1000, R("p_from"), R("p_to"));
        Add(t, "interpolate_pose", (m, line, a) =>
        {
            Pose from = P(a, 0, line, "interpolate_pose"), to = P(a, 1, line, "interpolate_pose");
            double alpha = Num(a, 2, line, "interpolate_pose", "alpha");
            return UrGeometry.FromPose(new Pose(from.Position + (to.Position - from.Position) * alpha, UrGeometry.Slerp(from.Rotation, to.Rotation, alpha)));
        }, R("p_from"), R("p_to"), R("alpha"));
    }

    private static Pose P(object[] a, int i, int line, string function) => UrGeometry.ToPose(Six(a, i, line, function, $"#{i + 1}"), line);
}
