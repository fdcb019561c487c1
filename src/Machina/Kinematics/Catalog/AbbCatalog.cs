namespace Machina;

/// <summary>
/// The ABB arms of the built-in catalogue. Lengths are OPW parameters in mm (a1, a2, c1, c2, c3, c4), ranges in degrees with ABB's
/// signs, speeds in °/s. Each entry names the file its numbers come from; docs/kinematics.md lists them all.
/// </summary>
internal static class AbbCatalog
{
    private static string AbbExperimental(string path, string? note = null) =>
        CatalogSource.Cite("ROS-Industrial abb_experimental (github.com/ros-industrial/abb_experimental, kinetic-devel 20b9cf8)", path, note);

    private static string AbbRosIndustrial(string path, string? note = null) =>
        CatalogSource.Cite("ROS-Industrial abb (github.com/ros-industrial/abb, kinetic-devel 77db19b)", path, note);

    private const string ProductSpecification = "ABB product specification (dimension drawing, axis working range, axis max speed)";

    private static Joints J(double a, double b, double c, double d, double e, double f) => CatalogSource.J(a, b, c, d, e, f);

    private static RobotModel Opw(string name, double a1, double a2, double c1, double c2, double c3, double c4, Joints min, Joints max, Joints? speeds, string source) =>
        CatalogSource.Opw("ABB", name, a1, a2, c1, c2, c3, c4, min, max, speeds, source);

    internal static RobotModel[] Build() =>
    [
            Opw("IRB 120", 0, -70, 290, 270, 302, 72,
                J(-165, -110, -110, -160, -120, -400), J(165, 110, 70, 160, 120, 400), J(250, 250, 250, 320, 320, 420),
                AbbExperimental("abb_irb120_support/urdf/irb120_3_58_macro.xacro")),
            Opw("IRB 120T", 0, -70, 290, 270, 302, 72,
                J(-165, -110, -110, -160, -120, -400), J(165, 110, 70, 160, 120, 400), J(250, 250, 250, 420, 590, 600),
                AbbExperimental("abb_irb120_support/urdf/irb120t_3_58_macro.xacro")),
            Opw("IRB 1200-5/0.9", 0, -42, 399.1, 448, 451, 82,
                J(-170, -100, -200, -270, -130, -360), J(170, 130, 70, 270, 130, 360), J(288, 240, 300, 400, 405, 600),
                AbbExperimental("abb_irb1200_support/urdf/irb1200_5_90_macro.xacro")),
            Opw("IRB 1200-7/0.7", 0, -42, 399.1, 350, 351, 82,
                J(-170, -100, -200, -270, -130, -360), J(170, 135, 70, 270, 130, 360), J(288, 240, 300, 400, 405, 600),
                AbbExperimental("abb_irb1200_support/urdf/irb1200_7_70_macro.xacro")),
            Opw("IRB 1600-6/1.2", 150, 0, 486.5, 475, 600, 65,
                J(-180, -63, -235, -200, -115, -400), J(180, 110, 55, 200, 115, 400), J(150, 160, 170, 320, 400, 450),
                AbbExperimental("abb_irb1600_support/urdf/irb1600_6_12_macro.xacro")),
            Opw("IRB 1600-8/1.45", 150, 0, 486.5, 700, 600, 65,
                J(-180, -90, -245, -200, -115, -400), J(180, 120, 65, 200, 115, 400), J(180, 180, 200, 400, 400, 460),
                AbbExperimental("abb_irb1600_support/urdf/irb1600_8_145_macro.xacro")),
            Opw("IRB 2600-12/1.65", 150, -115, 445, 700, 795, 85,
                J(-180, -95, -180, -400, -120, -400), J(180, 155, 75, 400, 120, 400), J(175, 175, 175, 360, 360, 500),
                AbbExperimental("abb_irb2600_support/urdf/irb2600_12_165_macro.xacro", "axes 2 and 3 from the ABB IRB 2600 product specification (the URDF mirrors axis 2 and cuts axis 3 to −155°)")),
            Opw("IRB 4600-20/2.50", 175, -175, 495, 1095, 1230.5, 85,
                J(-180, -90, -180, -400, -125, -400), J(180, 150, 75, 400, 120, 400), J(175, 175, 175, 360, 360, 500),
                AbbExperimental("abb_irb4600_support/urdf/irb4600_20_250_macro.xacro")),
            Opw("IRB 4600-40/2.55", 175, -175, 495, 1095, 1270, 135,
                J(-180, -90, -180, -400, -125, -400), J(180, 150, 75, 400, 120, 400), J(175, 175, 175, 250, 250, 360),
                AbbExperimental("abb_irb4600_support/urdf/irb4600_40_255_macro.xacro")),
            Opw("IRB 4600-60/2.05", 175, -175, 495, 900, 960, 135,
                J(-180, -90, -180, -400, -125, -400), J(180, 150, 75, 400, 120, 400), J(175, 175, 175, 250, 250, 360),
                AbbExperimental("abb_irb4600_support/urdf/irb4600_60_205_macro.xacro")),
            Opw("IRB 52-7/1.2", 150, 0, 486.5, 475, 600, 65,
                J(-180, -63, -235, -200, -115, -400), J(180, 110, 55, 200, 115, 400), J(180, 180, 180, 180, 180, 180),
                AbbExperimental("abb_irb52_support/urdf/irb52_7_120_macro.xacro")),
            Opw("IRB 52-7/1.45", 150, 0, 486.5, 700, 600, 65,
                J(-180, -90, -245, -200, -115, -400), J(180, 120, 65, 200, 115, 400), J(180, 180, 180, 180, 180, 180),
                AbbExperimental("abb_irb52_support/urdf/irb52_7_145_macro.xacro")),
            Opw("IRB 6600-225/2.55", 320, -200, 780, 1075, 1142, 200,
                J(-180, -65, -180, -300, -120, -300), J(180, 80, 60, 300, 120, 300), J(100, 90, 90, 150, 120, 190),
                AbbRosIndustrial("abb_irb6600_support/urdf/irb6600_225_255_macro.xacro")),
            Opw("IRB 6640-185/2.80", 320, -200, 780, 1075, 1392, 200,
                J(-170, -65, -180, -300, -120, -360), J(170, 85, 70, 300, 120, 360), J(100, 90, 90, 170, 140, 190),
                AbbRosIndustrial("abb_irb6640_support/urdf/irb6640_185_280_macro.xacro")),
            Opw("IRB 6650S-125/3.50", 600, -200, 630, 1280, 1592, 200,
                J(-180, -40, -180, -300, -120, -360), J(180, 160, 70, 300, 120, 360), J(110, 90, 90, 150, 120, 235),
                AbbExperimental("abb_irb6650s_support/urdf/irb6650s_125_350_macro.xacro")),
            Opw("IRB 6650S-90/3.90", 600, -200, 630, 1280, 2042, 200,
                J(-180, -40, -180, -300, -120, -360), J(180, 160, 70, 300, 120, 360), J(100, 90, 90, 150, 120, 235),
                AbbExperimental("abb_irb6650s_support/urdf/irb6650s_90_390_macro.xacro")),
            Opw("IRB 6700-200/2.60", 320, -200, 780, 1125, 1142.5, 200,
                J(-170, -65, -180, -300, -130, -360), J(170, 85, 70, 300, 130, 360), J(110, 110, 110, 190, 150, 210),
                AbbExperimental("abb_irb6700_support/urdf/irb6700_200_260_macro.xacro")),
            Opw("IRB 6700-235/2.65", 320, -200, 780, 1135, 1182.5, 200,
                J(-170, -65, -180, -300, -130, -360), J(170, 85, 70, 300, 130, 360), J(100, 90, 90, 170, 120, 190),
                AbbExperimental("abb_irb6700_support/urdf/irb6700_235_265_macro.xacro")),
            Opw("IRB 7600-150/3.50", 410, -165, 780, 1075, 2012, 250,
                J(-180, -60, -180, -300, -100, -360), J(180, 85, 60, 300, 100, 360), J(100, 60, 60, 100, 100, 190),
                AbbExperimental("abb_irb7600_support/urdf/irb7600_150_350_macro.xacro")),
            // Same arm as the IRB 2600-12/1.65 (ABB IRB 2600 product specification: the -12/1.65 and -20/1.65 share lengths, ranges and speeds).
            Opw("IRB 2600-20/1.65", 150, -115, 445, 700, 795, 85,
                J(-180, -95, -180, -400, -120, -400), J(180, 155, 75, 400, 120, 400), J(175, 175, 175, 360, 360, 500),
                AbbExperimental("abb_irb2600_support/urdf/irb2600_12_165_macro.xacro", "the IRB 2600-20/1.65 shares the -12/1.65 arm (ABB IRB 2600 product specification); axes 2 and 3 from that specification")),
            // No ROS-Industrial description: lengths 352/70/360/380/65 from the product specification's dimension drawing (also in the ARTE
            // toolbox robots/ABB/IRB140/parameters.m and the RobotStudio SDK IRB140 example); ranges +180/−180, +110/−90, +50/−230, ±200,
            // ±115 (ARTE has ±120: the narrower kept), ±400; speeds 200, 200, 260, 360, 360, 450 (ARTE agrees).
            Opw("IRB 140", 70, 0, 352, 360, 380, 65,
                J(-180, -90, -230, -200, -115, -400), J(180, 110, 50, 200, 115, 400), J(200, 200, 260, 360, 360, 450),
                $"{ProductSpecification}: IRB 140 (3HAC041346-001); cross-checked with the ARTE toolbox robots/ABB/IRB140/parameters.m"),
            // No ROS-Industrial description: the robotkinematicscatalogue modified-DH table of the IRB 6700-205/2.80 (780 / 320 / 1280 / 200 /
            // 1182.5 / 200) and the IRB 6700 ranges; no published joint speeds were found, so none are given (no speed check).
            Opw("IRB 6700-205/2.80", 320, -200, 780, 1280, 1182.5, 200,
                J(-170, -65, -180, -300, -130, -360), J(170, 85, 70, 300, 130, 360), null,
                $"{ProductSpecification}: IRB 6700 (3HAC044109-001); lengths cross-checked with the robotkinematicscatalogue package; joint speeds not published there"),
    ];
}
