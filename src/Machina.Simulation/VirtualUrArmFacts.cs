namespace Machina.Simulation;

/// <summary>
/// What the client interfaces tell of the arm itself (kinematics info and configuration data), in UR's units: its DH
/// parameters (m, rad), joint limits (rad) and speeds (rad/s), and the robot type number (UR3 3, UR5 1, UR10 2, UR16 4, UR20 7, UR30 8).
/// </summary>
internal sealed record VirtualUrArmFacts(double[] DhA, double[] DhD, double[] DhAlpha, double[] MinJoints, double[] MaxJoints, double[] MaxSpeeds,
    int RobotType, bool ESeries)
{
    /// <summary>The facts of a UR model (a UR5e when it has no UR DH parameters).</summary>
    public static VirtualUrArmFacts Of(RobotModel model)
    {
        UniversalRobotsDh dh = model.UniversalRobotsDh ?? RobotModels.Get("UR5e").UniversalRobotsDh!.Value;
        double[] Rad(Joints j) => [.. j.ToArray().Select(d => d * Math.PI / 180)];
        string name = model.Name;
        int type = name switch
        {
            _ when name.StartsWith("UR3", StringComparison.Ordinal) => 3,
            _ when name.StartsWith("UR10", StringComparison.Ordinal) => 2,
            _ when name.StartsWith("UR16", StringComparison.Ordinal) => 4,
            _ when name.StartsWith("UR20", StringComparison.Ordinal) => 7,
            _ when name.StartsWith("UR30", StringComparison.Ordinal) => 8,
            _ => 1,
        };
        bool eSeries = name.EndsWith('e') || type >= 7;
        return new VirtualUrArmFacts(
            [0, dh.A2 / 1000, dh.A3 / 1000, 0, 0, 0],
            [dh.D1 / 1000, 0, 0, dh.D4 / 1000, dh.D5 / 1000, dh.D6 / 1000],
            [Math.PI / 2, 0, 0, Math.PI / 2, -Math.PI / 2, 0],
            Rad(model.MinJoints), Rad(model.MaxJoints), Rad(model.MaxJointSpeeds ?? new Joints(180, 180, 180, 180, 180, 180)),
            type, eSeries);
    }
}
