namespace Machina;

/// <summary>
/// The Universal Robots arms of the built-in catalogue: UR's DH lengths in mm (d1, a2, a3, d4, d5, d6, UR's signs), ranges in degrees,
/// speeds in °/s, all as in UR's own description (Universal_Robots_ROS2_Description, config/&lt;model&gt;/default_kinematics.yaml and
/// joint_limits.yaml, which cite the UR user manuals), the same DH numbers as UR's support article "DH Parameters for calculations of
/// kinematics and dynamics".
/// </summary>
internal static class UniversalRobotsCatalog
{
    private static Joints J(double a, double b, double c, double d, double e, double f) => new(a, b, c, d, e, f);

    // ±360° on every joint except the elbow: ±180°, because the upper arm stops the forearm there ("due to the physical construction
    // of the robot, it's impossible to rotate the elbow_joint over more than approx ±1 pi", joint_limits.yaml). UR's data sheets print
    // ±360° for every joint; beyond ±180° the elbow would run into the arm, so those joint values are refused here.
    private static readonly Joints Min = J(-360, -360, -180, -360, -360, -360), Max = J(360, 360, 180, 360, 360, 360);

    private static RobotModel Ur(string name, double d1, double a2, double a3, double d4, double d5, double d6, Joints speeds) =>
        RobotModel.FromUniversalRobotsDh(name, new UniversalRobotsDh(d1, a2, a3, d4, d5, d6), Min, Max, speeds,
            $"Universal Robots, Universal_Robots_ROS2_Description (github.com/UniversalRobots/Universal_Robots_ROS2_Description, 2221ec0), "
            + $"config/{name.ToLowerInvariant()}/default_kinematics.yaml and joint_limits.yaml; DH as in UR's support article \"DH Parameters for calculations of kinematics and dynamics\"");

    internal static RobotModel[] Build()
    {
        Joints small = J(180, 180, 180, 360, 360, 360), medium = J(180, 180, 180, 180, 180, 180);
        Joints large = J(120, 120, 180, 180, 180, 180), heavy = J(120, 120, 150, 210, 210, 210);
        return
        [
            Ur("UR3", 151.9, -243.65, -213.25, 112.35, 85.35, 81.9, small),
            Ur("UR5", 89.159, -425, -392.25, 109.15, 94.65, 82.3, medium),
            Ur("UR10", 127.3, -612, -572.3, 163.941, 115.7, 92.2, large),
            Ur("UR3e", 151.85, -243.55, -213.2, 131.05, 85.35, 92.1, small),
            Ur("UR5e", 162.5, -425, -392.2, 133.3, 99.7, 99.6, medium),
            Ur("UR10e", 180.7, -612.7, -571.55, 174.15, 119.85, 116.55, large),
            Ur("UR16e", 180.7, -478.4, -360, 174.15, 119.85, 116.55, large),
            Ur("UR20", 236.3, -862, -728.7, 201, 159.3, 154.3, heavy),
            Ur("UR30", 236.3, -637, -503.7, 201, 159.3, 154.3, heavy),
        ];
    }
}
