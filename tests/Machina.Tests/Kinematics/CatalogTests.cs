namespace Machina.Tests.Kinematics;

/// <summary>
/// Every catalogued model against numbers written in its source, not computed by Machina: the flange (ABB tool0, KUKA FLANGE,
/// UR tool0) at the all-zero joints and at one more joint set. The expected values are the source's own chain (URDF joint origins,
/// axes and the tool0 frame of the named file, or UR's DH table chained as in UR's ur_macro.xacro) evaluated outside Machina and
/// written here literally, in mm and as a quaternion (w, x, y, z). At the zero pose each is the plain sum of the file's joint
/// origins. The three ABB models without a ROS-Industrial description are checked against their product-specification lengths
/// (sums written out). Joint values are the brand's own (KUKA A2 = 0: lower arm horizontal).
/// </summary>
public class CatalogTests
{
    private static Joints J(double a, double b, double c, double d, double e, double f) => new(a, b, c, d, e, f);

    private sealed record SourcePose(string Model, Joints Joints, double X, double Y, double Z, double Qw, double Qx, double Qy, double Qz);

    private static readonly SourcePose[] Poses =
    [
        // UR3: UR DH table in Universal_Robots_ROS2_Description config/ur3/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR3", J(0, 0, 0, 0, 0, 0), -456.9, -194.25, 66.55, 0.70711, 0.70711, 0, 0),
        new("UR3", J(30, -60, 80, -110, -70, 45), -282.78, -325.34, 213.01, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR5: UR DH table in Universal_Robots_ROS2_Description config/ur5/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR5", J(0, 0, 0, 0, 0, 0), -817.25, -191.45, -5.49, 0.70711, 0.70711, 0, 0),
        new("UR5", J(30, -60, 80, -110, -70, 45), -516.56, -456.78, 245.73, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR10: UR DH table in Universal_Robots_ROS2_Description config/ur10/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR10", J(0, 0, 0, 0, 0, 0), -1184.3, -256.14, 11.6, 0.70711, 0.70711, 0, 0),
        new("UR10", J(30, -60, 80, -110, -70, 45), -733.2, -649.03, 374.93, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR3e: UR DH table in Universal_Robots_ROS2_Description config/ur3e/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR3e", J(0, 0, 0, 0, 0, 0), -456.75, -223.15, 66.5, 0.70711, 0.70711, 0, 0),
        new("UR3e", J(30, -60, 80, -110, -70, 45), -271.6, -344.51, 203.31, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR5e: UR DH table in Universal_Robots_ROS2_Description config/ur5e/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR5e", J(0, 0, 0, 0, 0, 0), -817.2, -232.9, 62.8, 0.70711, 0.70711, 0, 0),
        new("UR5e", J(30, -60, 80, -110, -70, 45), -505.86, -485.32, 302.83, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR10e: UR DH table in Universal_Robots_ROS2_Description config/ur10e/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR10e", J(0, 0, 0, 0, 0, 0), -1184.25, -290.7, 60.85, 0.70711, 0.70711, 0, 0),
        new("UR10e", J(30, -60, 80, -110, -70, 45), -727.22, -666.98, 406.31, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR16e: UR DH table in Universal_Robots_ROS2_Description config/ur16e/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR16e", J(0, 0, 0, 0, 0, 0), -838.4, -290.7, 60.85, 0.70711, 0.70711, 0, 0),
        new("UR16e", J(30, -60, 80, -110, -70, 45), -496.91, -534.01, 362.36, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR20: UR DH table in Universal_Robots_ROS2_Description config/ur20/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR20", J(0, 0, 0, 0, 0, 0), -1590.7, -355.3, 77, 0.70711, 0.70711, 0, 0),
        new("UR20", J(30, -60, 80, -110, -70, 45), -977.34, -857.3, 588.59, 0.17216, 0.7813, 0.59951, -0.02267),
        // UR30: UR DH table in Universal_Robots_ROS2_Description config/ur30/default_kinematics.yaml, chained with urdf/ur_macro.xacro (tool0 in the controller base frame).
        new("UR30", J(0, 0, 0, 0, 0, 0), -1140.7, -355.3, 77, 0.70711, 0.70711, 0, 0),
        new("UR30", J(30, -60, 80, -110, -70, 45), -696.81, -695.34, 470.69, 0.17216, 0.7813, 0.59951, -0.02267),
        // IRB 120: abb_experimental abb_irb120_support/urdf/irb120_3_58_macro.xacro
        new("IRB 120", J(0, 0, 0, 0, 0, 0), 374, 0, 630, 0.70711, 0, 0.70711, 0),
        new("IRB 120", J(30, 20, -10, 40, 45, 60), 369.26, 250.98, 512.96, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 120T: abb_experimental abb_irb120_support/urdf/irb120t_3_58_macro.xacro
        new("IRB 120T", J(0, 0, 0, 0, 0, 0), 374, 0, 630, 0.70711, 0, 0.70711, 0),
        new("IRB 120T", J(30, 20, -10, 40, 45, 60), 369.26, 250.98, 512.96, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 1200-5/0.9: abb_experimental abb_irb1200_support/urdf/irb1200_5_90_macro.xacro
        new("IRB 1200-5/0.9", J(0, 0, 0, 0, 0, 0), 533, 0, 889.1, 0.70711, 0, 0.70711, 0),
        new("IRB 1200-5/0.9", J(30, 20, -10, 40, 45, 60), 547.79, 359.3, 729.32, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 1200-7/0.7: abb_experimental abb_irb1200_support/urdf/irb1200_7_70_macro.xacro
        new("IRB 1200-7/0.7", J(0, 0, 0, 0, 0, 0), 433, 0, 791.1, 0.70711, 0, 0.70711, 0),
        new("IRB 1200-7/0.7", J(30, 20, -10, 40, 45, 60), 433.48, 293.31, 654.59, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 1600-6/1.2: abb_experimental abb_irb1600_support/urdf/irb1600_6_12_macro.xacro
        new("IRB 1600-6/1.2", J(0, 0, 0, 0, 0, 0), 815, 0, 961.5, 0.70711, 0, 0.70711, 0),
        new("IRB 1600-6/1.2", J(30, 20, -10, 40, 45, 60), 801.45, 496.83, 786.01, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 1600-8/1.45: abb_experimental abb_irb1600_support/urdf/irb1600_8_145_macro.xacro
        new("IRB 1600-8/1.45", J(0, 0, 0, 0, 0, 0), 815, 0, 1186.5, 0.70711, 0, 0.70711, 0),
        new("IRB 1600-8/1.45", J(30, 20, -10, 40, 45, 60), 868.1, 535.31, 997.44, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 2400: abb abb_irb2400_support/urdf/irb2400_macro.xacro
        new("IRB 2400", J(0, 0, 0, 0, 0, 0), 940, 0, 1455, 0.70711, 0, 0.70711, 0),
        new("IRB 2400", J(30, 20, -10, 40, 45, 60), 984.66, 613.1, 1223.55, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 2600-12/1.65: abb_experimental abb_irb2600_support/urdf/irb2600_12_165_macro.xacro
        new("IRB 2600-12/1.65", J(0, 0, 0, 0, 0, 0), 1030, 0, 1260, 0.70711, 0, 0.70711, 0),
        new("IRB 2600-12/1.65", J(30, 20, -10, 40, 45, 60), 1057.59, 655.21, 1022.21, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 4400L-30/2.43: abb abb_irb4400_support/urdf/irb4400l_30_243_macro.xacro
        new("IRB 4400L-30/2.43", J(0, 0, 0, 0, 0, 0), 1720, 0, 1720, 0.70711, 0, 0.70711, 0),
        new("IRB 4400L-30/2.43", J(30, 20, -10, 40, 45, 60), 1677.55, 1042.01, 1332.54, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 4600-20/2.50: abb_experimental abb_irb4600_support/urdf/irb4600_20_250_macro.xacro
        new("IRB 4600-20/2.50", J(0, 0, 0, 0, 0, 0), 1490.5, 0, 1765, 0.70711, 0, 0.70711, 0),
        new("IRB 4600-20/2.50", J(30, 20, -10, 40, 45, 60), 1576.68, 954.91, 1426.85, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 4600-40/2.55: abb_experimental abb_irb4600_support/urdf/irb4600_40_255_macro.xacro
        new("IRB 4600-40/2.55", J(0, 0, 0, 0, 0, 0), 1580, 0, 1765, 0.70711, 0, 0.70711, 0),
        new("IRB 4600-40/2.55", J(30, 20, -10, 40, 45, 60), 1625.09, 1009.1, 1387.18, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 4600-60/2.05: abb_experimental abb_irb4600_support/urdf/irb4600_60_205_macro.xacro
        new("IRB 4600-60/2.05", J(0, 0, 0, 0, 0, 0), 1270, 0, 1570, 0.70711, 0, 0.70711, 0),
        new("IRB 4600-60/2.05", J(30, 20, -10, 40, 45, 60), 1302.94, 823.11, 1257.77, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 52-7/1.2: abb_experimental abb_irb52_support/urdf/irb52_7_120_macro.xacro
        new("IRB 52-7/1.2", J(0, 0, 0, 0, 0, 0), 815, 0, 961.5, 0.70711, 0, 0.70711, 0),
        new("IRB 52-7/1.2", J(30, 20, -10, 40, 45, 60), 801.45, 496.83, 786.01, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 52-7/1.45: abb_experimental abb_irb52_support/urdf/irb52_7_145_macro.xacro
        new("IRB 52-7/1.45", J(0, 0, 0, 0, 0, 0), 815, 0, 1186.5, 0.70711, 0, 0.70711, 0),
        new("IRB 52-7/1.45", J(30, 20, -10, 40, 45, 60), 868.1, 535.31, 997.44, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 6600-225/2.55: abb abb_irb6600_support/urdf/irb6600_225_255_macro.xacro
        new("IRB 6600-225/2.55", J(0, 0, 0, 0, 0, 0), 1662, 0, 2055, 0.70711, 0, 0.70711, 0),
        new("IRB 6600-225/2.55", J(30, 20, -10, 40, 45, 60), 1658.46, 1062.48, 1657.58, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 6640-185/2.80: abb abb_irb6640_support/urdf/irb6640_185_280_macro.xacro
        new("IRB 6640-185/2.80", J(0, 0, 0, 0, 0, 0), 1912, 0, 2055, 0.70711, 0, 0.70711, 0),
        new("IRB 6640-185/2.80", J(30, 20, -10, 40, 45, 60), 1871.68, 1185.58, 1614.17, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 6650S-125/3.50: abb_experimental abb_irb6650s_support/urdf/irb6650s_125_350_macro.xacro
        new("IRB 6650S-125/3.50", J(0, 0, 0, 0, 0, 0), 2392, 0, 2110, 0.70711, 0, 0.70711, 0),
        new("IRB 6650S-125/3.50", J(30, 20, -10, 40, 45, 60), 2345.46, 1459.12, 1622.07, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 6650S-90/3.90: abb_experimental abb_irb6650s_support/urdf/irb6650s_90_390_macro.xacro
        new("IRB 6650S-90/3.90", J(0, 0, 0, 0, 0, 0), 2842, 0, 2110, 0.70711, 0, 0.70711, 0),
        new("IRB 6650S-90/3.90", J(30, 20, -10, 40, 45, 60), 2729.25, 1680.7, 1543.93, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 6700-200/2.60: abb_experimental abb_irb6700_support/urdf/irb6700_200_260_macro.xacro
        new("IRB 6700-200/2.60", J(0, 0, 0, 0, 0, 0), 1662.5, 0, 2105, 0.70711, 0, 0.70711, 0),
        new("IRB 6700-200/2.60", J(30, 20, -10, 40, 45, 60), 1673.7, 1071.28, 1704.48, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 6700-235/2.65: abb_experimental abb_irb6700_support/urdf/irb6700_235_265_macro.xacro
        new("IRB 6700-235/2.65", J(0, 0, 0, 0, 0, 0), 1702.5, 0, 2115, 0.70711, 0, 0.70711, 0),
        new("IRB 6700-235/2.65", J(30, 20, -10, 40, 45, 60), 1710.78, 1092.68, 1706.93, 0.01471, -0.3845, -0.82479, -0.41433),
        // IRB 7600-150/3.50: abb_experimental abb_irb7600_support/urdf/irb7600_150_350_macro.xacro
        new("IRB 7600-150/3.50", J(0, 0, 0, 0, 0, 0), 2672, 0, 2020, 0.70711, 0, 0.70711, 0),
        new("IRB 7600-150/3.50", J(30, 20, -10, 40, 45, 60), 2487.86, 1567.57, 1439.22, 0.01471, -0.3845, -0.82479, -0.41433),
        // KR 3 R540: kuka_experimental kuka_kr3_support/urdf/kr3r540_macro.xacro
        new("KR 3 R540", J(0, 0, 0, 0, 0, 0), 615, 0, 365, 0.70711, 0, 0.70711, 0),
        new("KR 3 R540", J(30, -70, 100, 40, 45, 60), 303.13, -214.38, 414.94, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 5 arc: kuka_experimental kuka_kr5_support/urdf/kr5_arc_macro.xacro
        new("KR 5 arc", J(0, 0, 0, 0, 0, 0), 1515, 0, 520, 0.70711, 0, 0.70711, 0),
        new("KR 5 arc", J(30, -70, 100, 40, 45, 60), 858.44, -555.98, 663.13, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 10 R1100 sixx: kuka_experimental kuka_kr10_support/urdf/kr10r1100sixx_macro.xacro
        new("KR 10 R1100 sixx", J(0, 0, 0, 0, 0, 0), 1180, 0, 435, 0.70711, 0, 0.70711, 0),
        new("KR 10 R1100 sixx", J(30, -70, 100, 40, 45, 60), 594.41, -385.17, 633.23, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 10 R1420: kuka_experimental kuka_kr10_support/urdf/kr10r1420_macro.xacro
        new("KR 10 R1420", J(0, 0, 0, 0, 0, 0), 1500, 0, 470, 0.70711, 0, 0.70711, 0),
        new("KR 10 R1420", J(30, -70, 100, 40, 45, 60), 819.73, -515.26, 644.72, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 16-2: kuka_experimental kuka_kr16_support/urdf/kr16_2_macro.xacro
        new("KR 16-2", J(0, 0, 0, 0, 0, 0), 1768, 0, 640, 0.70711, 0, 0.70711, 0),
        new("KR 16-2", J(30, -70, 100, 40, 45, 60), 924.75, -616.83, 818.7, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 120 R2500 pro: kuka_experimental kuka_kr120_support/urdf/kr120r2500pro_macro.xacro
        new("KR 120 R2500 pro", J(0, 0, 0, 0, 0, 0), 2715, 0, 634, 0.70711, 0, 0.70711, 0),
        new("KR 120 R2500 pro", J(30, -70, 100, 40, 45, 60), 1390.71, -915.77, 1043.27, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 150-2: kuka_experimental kuka_kr150_support/urdf/kr150_2_macro.xacro
        new("KR 150-2", J(0, 0, 0, 0, 0, 0), 2930, 0, 695, 0.70711, 0, 0.70711, 0),
        new("KR 150-2", J(30, -70, 100, 40, 45, 60), 1490.3, -981.14, 1137.77, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 10 R1100-2: kuka_robot_descriptions kuka_agilus_support/urdf/kr10_r1100_2_macro.xacro
        new("KR 10 R1100-2", J(0, 0, 0, 0, 0, 0), 1190, 0, 425, 0.70711, 0, 0.70711, 0),
        new("KR 10 R1100-2", J(30, -70, 100, 40, 45, 60), 590.76, -388.31, 616.34, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 10 R1100-3: kuka_robot_descriptions kuka_agilus_support/urdf/kr10_r1100_3_macro.xacro
        new("KR 10 R1100-3", J(0, 0, 0, 0, 0, 0), 1190, 0, 435, 0.70711, 0, 0.7071, -0.00001),
        new("KR 10 R1100-3", J(30, -70, 100, 40, 45, 60), 595.1, -390.81, 625, 0.10513, 0.44225, -0.84602, 0.27861),
        // KR 10 R900-2: kuka_robot_descriptions kuka_agilus_support/urdf/kr10_r900_2_macro.xacro (same in kuka_experimental kuka_kr10_support/urdf/kr10r900_2_macro.xacro)
        new("KR 10 R900-2", J(0, 0, 0, 0, 0, 0), 990, 0, 425, 0.70711, 0, 0.70711, 0),
        new("KR 10 R900-2", J(30, -70, 100, 40, 45, 60), 488.41, -329.22, 565.17, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 13 R900-3: kuka_robot_descriptions kuka_agilus_support/urdf/kr13_r900_3_macro.xacro
        new("KR 13 R900-3", J(0, 0, 0, 0, 0, 0), 990, 0, 435, 0.70711, 0, 0.7071, -0.00001),
        new("KR 13 R900-3", J(30, -70, 100, 40, 45, 60), 490.47, -330.41, 581.03, 0.10513, 0.44225, -0.84602, 0.27861),
        // KR 16 R1100-3: kuka_robot_descriptions kuka_agilus_support/urdf/kr16_r1100_3_macro.xacro
        new("KR 16 R1100-3", J(0, 0, 0, 0, 0, 0), 1190, 0, 550, 0.70711, 0, 0.7071, -0.00001),
        new("KR 16 R1100-3", J(30, -70, 100, 40, 45, 60), 637.52, -415.3, 689.11, 0.10513, 0.44225, -0.84602, 0.27861),
        // KR 4 R600: kuka_robot_descriptions kuka_agilus_support/urdf/kr4_r600_macro.xacro
        new("KR 4 R600", J(0, 0, 0, 0, 0, 0), 675, 0, 350, 0.70711, 0, 0.70711, 0),
        new("KR 4 R600", J(30, -70, 100, 40, 45, 60), 332.2, -231.16, 403.13, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 6 R700-2: kuka_robot_descriptions kuka_agilus_support/urdf/kr6_r700_2_macro.xacro
        new("KR 6 R700-2", J(0, 0, 0, 0, 0, 0), 815, 0, 425, 0.70711, 0, 0.70711, 0),
        new("KR 6 R700-2", J(30, -70, 100, 40, 45, 60), 411.62, -284.88, 479.91, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 6 R700 sixx: kuka_robot_descriptions kuka_agilus_support/urdf/kr6_r700_sixx_macro.xacro (same in kuka_experimental kuka_kr6_support/urdf/kr6r700sixx_macro.xacro)
        new("KR 6 R700 sixx", J(0, 0, 0, 0, 0, 0), 785, 0, 435, 0.70711, 0, 0.70711, 0),
        new("KR 6 R700 sixx", J(30, -70, 100, 40, 45, 60), 409.34, -278.32, 478, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 6 R900-2: kuka_robot_descriptions kuka_agilus_support/urdf/kr6_r900_2_macro.xacro (same in kuka_experimental kuka_kr6_support/urdf/kr6r900_2_macro.xacro)
        new("KR 6 R900-2", J(0, 0, 0, 0, 0, 0), 990, 0, 425, 0.70711, 0, 0.70711, 0),
        new("KR 6 R900-2", J(30, -70, 100, 40, 45, 60), 488.41, -329.22, 565.17, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 6 R900 sixx: kuka_robot_descriptions kuka_agilus_support/urdf/kr6_r900_sixx_macro.xacro (same in kuka_experimental kuka_kr6_support/urdf/kr6r900sixx_macro.xacro)
        new("KR 6 R900 sixx", J(0, 0, 0, 0, 0, 0), 980, 0, 435, 0.70711, 0, 0.70711, 0),
        new("KR 6 R900 sixx", J(30, -70, 100, 40, 45, 60), 492.06, -326.08, 582.06, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 7 R900-3: kuka_robot_descriptions kuka_agilus_support/urdf/kr7_r900_3_macro.xacro
        new("KR 7 R900-3", J(0, 0, 0, 0, 0, 0), 977, 0, 387, 0.70711, 0, 0.70711, 0),
        new("KR 7 R900-3", J(30, -70, 100, 40, 45, 60), 519.5, -340.35, 482.9, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 12 R1450-3 HW: kuka_robot_descriptions kuka_cybertech_support/urdf/kr12_r1450_3_hw_macro.xacro
        new("KR 12 R1450-3 HW", J(0, 0, 0, 0, 0, 0), 1505.2, 0, 562, 0.70711, 0, 0.70711, 0),
        new("KR 12 R1450-3 HW", J(30, -70, 100, 40, 45, 60), 920.8, -573.61, 647.13, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 16 R1610-2: kuka_robot_descriptions kuka_cybertech_support/urdf/kr16_r1610_2_macro.xacro
        new("KR 16 R1610-2", J(0, 0, 0, 0, 0, 0), 1748, 0, 670, 0.70711, 0, 0.70711, 0),
        new("KR 16 R1610-2", J(30, -70, 100, 40, 45, 60), 936.28, -620.86, 929.5, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 16 R2010-2: kuka_robot_descriptions kuka_cybertech_support/urdf/kr16_r2010_2_macro.xacro
        new("KR 16 R2010-2", J(0, 0, 0, 0, 0, 0), 2153, 0, 670, 0.70711, 0, 0.70711, 0),
        new("KR 16 R2010-2", J(30, -70, 100, 40, 45, 60), 1149.27, -743.83, 1014.94, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 20 R1810-2: kuka_robot_descriptions kuka_cybertech_support/urdf/kr20_r1810_2_macro.xacro
        new("KR 20 R1810-2", J(0, 0, 0, 0, 0, 0), 1953, 0, 670, 0.70711, 0, 0.70711, 0),
        new("KR 20 R1810-2", J(30, -70, 100, 40, 45, 60), 1090.03, -709.63, 827, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 20 R1820-2 E: kuka_robot_descriptions kuka_cybertech_support/urdf/kr20_r1820_2_e_macro.xacro
        new("KR 20 R1820-2 E", J(0, 0, 0, 0, 0, 0), 1933.3, 0, 703.5, 0.70711, 0, 0.7071, -0.00001),
        new("KR 20 R1820-2 E", J(30, -70, 100, 40, 45, 60), 1103.9, -705.82, 894.94, 0.10513, 0.44225, -0.84602, 0.27861),
        // KR 8 R1440-2 arc HW: kuka_robot_descriptions kuka_cybertech_support/urdf/kr8_r1440_2_arc_hw_macro.xacro
        new("KR 8 R1440-2 arc HW", J(0, 0, 0, 0, 0, 0), 1487, 0, 635, 0.70711, 0, 0.70711, 0),
        new("KR 8 R1440-2 arc HW", J(30, -70, 100, 40, 45, 60), 894.57, -558.47, 800.77, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 8 R2100-2 arc HW: kuka_robot_descriptions kuka_cybertech_support/urdf/kr8_r2100_2_arc_hw_macro.xacro
        new("KR 8 R2100-2 arc HW", J(0, 0, 0, 0, 0, 0), 2155, 0, 740, 0.70711, 0, 0.70711, 0),
        new("KR 8 R2100-2 arc HW", J(30, -70, 100, 40, 45, 60), 1230.83, -752.61, 1098.11, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 240 R3330: kuka_robot_descriptions kuka_fortec_support/urdf/kr240_r3330_macro.xacro
        new("KR 240 R3330", J(0, 0, 0, 0, 0, 0), 3615, 0, 990, 0.70711, 0, 0.70711, 0),
        new("KR 240 R3330", J(30, -70, 100, 40, 45, 60), 1957.87, -1282.58, 1217.9, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 300 R2800-2 MT: kuka_robot_descriptions kuka_fortec_support/urdf/kr300_r2800_2_mt_macro.xacro
        new("KR 300 R2800-2 MT", J(0, 0, 0, 0, 0, 0), 3089.5, 0, 1040, 0.70711, 0, 0.70711, 0),
        new("KR 300 R2800-2 MT", J(30, -70, 100, 40, 45, 60), 1677.98, -1128.85, 1422.34, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 360 R2830: kuka_robot_descriptions kuka_fortec_support/urdf/kr360_r2830_macro.xacro
        new("KR 360 R2830", J(0, 0, 0, 0, 0, 0), 3115, 0, 990, 0.70711, 0, 0.70711, 0),
        new("KR 360 R2830", J(30, -70, 100, 40, 45, 60), 1582.87, -1066.08, 1467.9, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 500 R2800-2: kuka_robot_descriptions kuka_fortec_support/urdf/kr500_r2800_2_macro.xacro
        new("KR 500 R2800-2", J(0, 0, 0, 0, 0, 0), 3075.5, 0, 950, 0.70711, 0, 0.70711, 0),
        new("KR 500 R2800-2", J(30, -70, 100, 40, 45, 60), 1667.43, -1112.8, 1349.49, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 560 R3100-2: kuka_robot_descriptions kuka_fortec_support/urdf/kr560_r3100_2_macro.xacro
        new("KR 560 R3100-2", J(0, 0, 0, 0, 0, 0), 3389.5, 0, 1040, 0.70711, 0, 0.70711, 0),
        new("KR 560 R3100-2", J(30, -70, 100, 40, 45, 60), 1766.84, -1180.16, 1704.25, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 600 R2830: kuka_robot_descriptions kuka_fortec_support/urdf/kr600_r2830_macro.xacro
        new("KR 600 R2830", J(0, 0, 0, 0, 0, 0), 3115, 0, 990, 0.70711, 0, 0.70711, 0),
        new("KR 600 R2830", J(30, -70, 100, 40, 45, 60), 1582.87, -1066.08, 1467.9, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 800 R2800-2: kuka_robot_descriptions kuka_fortec_support/urdf/kr800_r2800_2_macro.xacro
        new("KR 800 R2800-2", J(0, 0, 0, 0, 0, 0), 3089.5, 0, 1040, 0.70711, 0, 0.70711, 0),
        new("KR 800 R2800-2", J(30, -70, 100, 40, 45, 60), 1677.98, -1128.85, 1422.34, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 20 R3100: kuka_robot_descriptions kuka_iontec_support/urdf/kr20_r3100_macro.xacro
        new("KR 20 R3100", J(0, 0, 0, 0, 0, 0), 3253, 0, 625, 0.70711, 0, 0.70711, 0),
        new("KR 20 R3100", J(30, -70, 100, 40, 45, 60), 1792.03, -1114.93, 887.14, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 30 R2100: kuka_robot_descriptions kuka_iontec_support/urdf/kr30_r2100_macro.xacro
        new("KR 30 R2100", J(0, 0, 0, 0, 0, 0), 2285, 0, 625, 0.70711, 0, 0.70711, 0),
        new("KR 30 R2100", J(30, -70, 100, 40, 45, 60), 1225.75, -804.78, 784.94, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 50 R2100: kuka_robot_descriptions kuka_iontec_support/urdf/kr50_r2100_macro.xacro
        new("KR 50 R2100", J(0, 0, 0, 0, 0, 0), 2285, 0, 625, 0.70711, 0, 0.70711, 0),
        new("KR 50 R2100", J(30, -70, 100, 40, 45, 60), 1225.75, -804.78, 784.94, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 50 R2500: kuka_robot_descriptions kuka_iontec_support/urdf/kr50_r2500_macro.xacro
        new("KR 50 R2500", J(0, 0, 0, 0, 0, 0), 2685, 0, 625, 0.70711, 0, 0.70711, 0),
        new("KR 50 R2500", J(30, -70, 100, 40, 45, 60), 1344.23, -873.18, 1160.81, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 70 R2100: kuka_robot_descriptions kuka_iontec_support/urdf/kr70_r2100_macro.xacro
        new("KR 70 R2100", J(0, 0, 0, 0, 0, 0), 2285, 0, 625, 0.70711, 0, 0.70711, 0),
        new("KR 70 R2100", J(30, -70, 100, 40, 45, 60), 1225.75, -804.78, 784.94, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 120 R2700-2: kuka_robot_descriptions kuka_quantec_support/urdf/kr120_r2700_2_macro.xacro
        new("KR 120 R2700-2", J(0, 0, 0, 0, 0, 0), 2915, 0, 760, 0.70711, 0, 0.7071, -0.00001),
        new("KR 120 R2700-2", J(30, -70, 100, 40, 45, 60), 1605.95, -1040.03, 1038.38, 0.10513, 0.44225, -0.84602, 0.27861),
        // KR 150 R3100-2: kuka_robot_descriptions kuka_quantec_support/urdf/kr150_r3100_2_macro.xacro (same in kuka_experimental kuka_kr150_support/urdf/kr150r3100_2_macro.xacro)
        new("KR 150 R3100-2", J(0, 0, 0, 0, 0, 0), 3315, 0, 760, 0.70711, 0, 0.70711, 0),
        new("KR 150 R3100-2", J(30, -70, 100, 40, 45, 60), 1815.18, -1160.84, 1126.31, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 210 R2700-2: kuka_robot_descriptions kuka_quantec_support/urdf/kr210_r2700_2_macro.xacro
        new("KR 210 R2700-2", J(0, 0, 0, 0, 0, 0), 2915, 0, 760, 0.70711, 0, 0.70711, 0),
        new("KR 210 R2700-2", J(30, -70, 100, 40, 45, 60), 1605.94, -1040.03, 1038.37, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 210 R3100-2: kuka_robot_descriptions kuka_quantec_support/urdf/kr210_r3100_2_macro.xacro
        new("KR 210 R3100-2", J(0, 0, 0, 0, 0, 0), 3340, 0, 760, 0.70711, 0, 0.70711, 0),
        new("KR 210 R3100-2", J(30, -70, 100, 40, 45, 60), 1816.9, -1174.95, 1105.74, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 210 R3300-2 K: kuka_robot_descriptions kuka_quantec_support/urdf/kr210_r3300_2_k_macro.xacro
        new("KR 210 R3300-2 K", J(0, 0, 0, 0, 0, 0), 3540, 0, 665, 0.70711, 0, 0.70711, 0),
        new("KR 210 R3300-2 K", J(30, -70, 100, 40, 45, 60), 2013.31, -1288.34, 1110.74, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 240 R2900-2: kuka_robot_descriptions kuka_quantec_support/urdf/kr240_r2900_2_macro.xacro
        new("KR 240 R2900-2", J(0, 0, 0, 0, 0, 0), 3140, 0, 760, 0.70711, 0, 0.70711, 0),
        new("KR 240 R2900-2", J(30, -70, 100, 40, 45, 60), 1666.9, -1088.34, 1205.74, 0.10514, 0.44224, -0.84602, 0.2786),
        // KR 300 R2700-2: kuka_robot_descriptions kuka_quantec_support/urdf/kr300_r2700_2_macro.xacro
        new("KR 300 R2700-2", J(0, 0, 0, 0, 0, 0), 2940, 0, 760, 0.70711, 0, 0.70711, 0),
        new("KR 300 R2700-2", J(30, -70, 100, 40, 45, 60), 1607.66, -1054.14, 1017.8, 0.10514, 0.44224, -0.84602, 0.2786),
        // No ROS-Industrial description: ABB product specification lengths (see docs/kinematics.md). Zero: [a1 + c3 + c4, 0, c1 + c2 − a2],
        // tool0 Z forward; axis 5 at 90°: [a1 + c3, 0, c1 + c2 − a2 − c4], tool0 Z down.
        new("IRB 140", J(0, 0, 0, 0, 0, 0), 70 + 380 + 65, 0, 352 + 360 - 0, 0.70711, 0, 0.70711, 0),
        new("IRB 140", J(0, 0, 0, 0, 90, 0), 70 + 380, 0, 352 + 360 - 0 - 65, 0, 0, 1, 0),
        new("IRB 2600-20/1.65", J(0, 0, 0, 0, 0, 0), 150 + 795 + 85, 0, 445 + 700 + 115, 0.70711, 0, 0.70711, 0),
        new("IRB 2600-20/1.65", J(0, 0, 0, 0, 90, 0), 150 + 795, 0, 445 + 700 + 115 - 85, 0, 0, 1, 0),
        new("IRB 6700-205/2.80", J(0, 0, 0, 0, 0, 0), 320 + 1182.5 + 200, 0, 780 + 1280 + 200, 0.70711, 0, 0.70711, 0),
        new("IRB 6700-205/2.80", J(0, 0, 0, 0, 90, 0), 320 + 1182.5, 0, 780 + 1280 + 200 - 200, 0, 0, 1, 0),
    ];

    public static TheoryData<string> Models()
    {
        var data = new TheoryData<string>();
        foreach (RobotModel m in RobotModels.All)
        {
            data.Add(m.Name);
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Models))]
    public void Forward_CatalogModel_MatchesItsSource(string name)
    {
        RobotModel model = RobotModels.Get(name);
        SourcePose[] rows = Poses.Where(p => p.Model == name).ToArray();
        Assert.True(rows.Length >= 2, $"{name}: every catalogued model needs its zero pose and one more pose from its source in this table.");
        foreach (SourcePose row in rows)
        {
            var expected = new Pose(row.X, row.Y, row.Z, Rotation.FromQuaternion(row.Qw, row.Qx, row.Qy, row.Qz));
            Pose actual = model.Kinematics.Forward(row.Joints);
            // 0.1 mm: the sources give lengths to 0.1 mm or better; some KUKA files round their frame rotations (1.5708 for π/2).
            Assert.True(expected.IsSimilar(actual, 0.1, 0.01), $"{name} at {row.Joints}: source says {expected}, Machina gives {actual}");
        }
    }

    [Fact]
    public void All_HasAtLeast60ArmsEachWithSourceLimitsAndSpeeds()
    {
        Assert.True(RobotModels.All.Count >= 60, $"only {RobotModels.All.Count} models");
        Assert.Equal(RobotModels.All.Count, RobotModels.All.Select(m => m.Name).Distinct().Count());
        foreach (RobotModel m in RobotModels.All)
        {
            Assert.False(string.IsNullOrWhiteSpace(m.Source), m.Name);
            Assert.Same(m, RobotModels.Find(m.Name));
            // The IRB 6700-205/2.80 is the one arm whose joint speeds no source gave (kept because users' code names it).
            Assert.True(m.MaxJointSpeeds is not null || m.Name == "IRB 6700-205/2.80", $"{m.Name} has no joint speeds");
        }
        Assert.True(RobotModels.All.Count(m => m.Brand == "ABB") >= 20);
        Assert.True(RobotModels.All.Count(m => m.Brand == "KUKA") >= 30);
        Assert.Equal(9, RobotModels.All.Count(m => m.Brand == "UR"));
    }

    [Theory]
    [InlineData("IRB 4600-20/2.50")]
    [InlineData("KR 5 arc")]
    [InlineData("KR 16-2")]
    [InlineData("KR 16")]     // the name used before: still found
    public void Find_NewAndOldNames_AreCatalogued(string name) => Assert.NotNull(RobotModels.Find(name));

    // Joint ranges that looked mirrored or copied (issue 13), in the brand's own signs. Sources in docs/kinematics.md.
    [Theory]
    // ABB IRB 2600 product specification: axis 2 +155° (forward) to −95°; axis 3 +75° to −180°. (ROS-Industrial's irb2600_12_165_macro
    // has axis 2 −155/+95 and axis 3 −155/+75: mirrored there, not here; its axis +Y is ABB's positive direction.)
    [InlineData("IRB 2600-12/1.65", 2, -95, 155)]
    [InlineData("IRB 2600-12/1.65", 3, -180, 75)]
    // KR QUANTEC: A2 −140° to −5° (kuka_robot_descriptions, every QUANTEC); the kuka_experimental kr120r2500pro URDF repeats the
    // KR 16-2 ranges (−155/35, −130/154) and speeds verbatim, a copy.
    [InlineData("KR 120 R2500 pro", 2, -140, -5)]
    [InlineData("KR 120 R2500 pro", 3, -120, 155)]
    // ABB IRB 140: axis 2 +110/−90, axis 3 +50/−230, axis 5 ±115 (sources disagree on axis 5, ±115 or ±120: the narrower is kept).
    [InlineData("IRB 140", 2, -90, 110)]
    [InlineData("IRB 140", 3, -230, 50)]
    [InlineData("IRB 140", 5, -115, 115)]
    // UR elbow: ±180° — the arm's own construction stops it there (Universal_Robots_ROS2_Description config/*/joint_limits.yaml).
    [InlineData("UR5e", 3, -180, 180)]
    [InlineData("UR20", 3, -180, 180)]
    [InlineData("UR3", 3, -180, 180)]
    // IRB 1200: axis 2 +130° on the 5/0.9, +135° on the 7/0.7 (abb_experimental irb1200 macros).
    [InlineData("IRB 1200-5/0.9", 2, -100, 130)]
    [InlineData("IRB 1200-7/0.7", 2, -100, 135)]
    public void Limits_CheckedAxes_MatchTheSources(string name, int axis, double min, double max)
    {
        RobotModel m = RobotModels.Get(name);
        Assert.Equal(min, m.MinJoints[axis - 1]);
        Assert.Equal(max, m.MaxJoints[axis - 1]);
    }

    [Fact]
    public void Kr16_ForearmOffsetAndBaseHeight_MatchRosIndustrial()
    {
        // kuka_experimental kuka_kr16_support/urdf/kr16_2_macro.xacro: joint_a4 origin z = −0.035 (the forearm runs 35 mm below axis 3),
        // joint_a6-flange x = 0.158. Home {0, −90, 90, 0, 0, 0}: x = 0.260 + 0.670 + 0.158, z = 0.675 + 0.680 − 0.035.
        Pose home = RobotModels.Get("KR 16-2").Kinematics.Forward(J(0, -90, 90, 0, 0, 0));
        Assert.True(home.Position.IsSimilar(new Vector(1088, 0, 1320), 1e-6), home.ToString());
        // abb_experimental irb1200 macros: joint_1 origin z = 0.3991 (the IRB 1200 axis 2 is 399.1 mm above the base).
        Assert.Equal(399.1, RobotModels.Get("IRB 1200-5/0.9").Opw!.Value.C1);
        Assert.Equal(399.1, RobotModels.Get("IRB 1200-7/0.7").Opw!.Value.C1);
    }
}
