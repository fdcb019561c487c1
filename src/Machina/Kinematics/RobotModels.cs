namespace Machina;

/// <summary>
/// The built-in catalogue of robot models (read-only). The source of every number is listed in docs/kinematics.md and in each
/// model's <see cref="RobotModel.Source"/>.
/// </summary>
public static class RobotModels
{
    private const string UrDh = "Universal Robots, \"DH Parameters for calculations of kinematics and dynamics\" (universal-robots.com support article)";
    private const string UrSpec = "Universal Robots technical specifications / user manual (joint ranges ±360°, maximum joint speeds)";
    private const string AbbSpec = "ABB product specification (dimension drawings, axis working range, axis max speed)";
    private const string KukaSpec = "KUKA specification / data sheet (dimension drawings, axis range, axis speed with rated payload)";

    private static readonly RobotModel[] Models = Build();

    /// <summary>Every catalogued model.</summary>
    public static IReadOnlyList<RobotModel> All { get; } = Array.AsReadOnly(Models);

    /// <summary>The model with this name (case, spaces, dashes and slashes ignored), or null when there is none.</summary>
    public static RobotModel? Find(string name)
    {
        ArgumentNullException.ThrowIfNull(name);
        string key = Key(name);
        foreach (RobotModel m in Models)
        {
            if (Key(m.Name) == key)
            {
                return m;
            }
        }
        return null;
    }

    /// <summary>The model with this name; throws an <see cref="ArgumentException"/> listing similar names when there is none.</summary>
    public static RobotModel Get(string name)
    {
        RobotModel? m = Find(name);
        if (m is not null)
        {
            return m;
        }
        string key = Key(name);
        var close = Models.Where(x => key.Length > 0 && (Key(x.Name).Contains(key, StringComparison.Ordinal) || key.Contains(Key(x.Name), StringComparison.Ordinal)
                || Key(x.Name).StartsWith(key[..Math.Min(key.Length, 4)], StringComparison.Ordinal)))
            .Select(x => x.Name).ToList();
        string hint = close.Count > 0 ? $"Did you mean: {string.Join(", ", close)}?" : $"Known models: {string.Join(", ", Models.Select(x => x.Name))}.";
        throw new ArgumentException($"There is no robot model called \"{name}\". {hint}", nameof(name));
    }

    private static string Key(string s) =>
        new(s.Where(c => char.IsLetterOrDigit(c) || c == '.').Select(char.ToLowerInvariant).ToArray());

    private static Joints J(double a, double b, double c, double d, double e, double f) => new(a, b, c, d, e, f);

    private static RobotModel Ur(string name, double d1, double a2, double a3, double d4, double d5, double d6, Joints speeds) =>
        RobotModel.FromUniversalRobotsDh(name, new UniversalRobotsDh(d1, a2, a3, d4, d5, d6),
            J(-360, -360, -360, -360, -360, -360), J(360, 360, 360, 360, 360, 360), speeds, $"{UrDh}; {UrSpec}");

    private static RobotModel Opw(string brand, string name, double a1, double a2, double c1, double c2, double c3, double c4, Joints min, Joints max, Joints speeds, string source) =>
        RobotModel.FromOpw(name, brand, new OpwParameters(a1, a2, 0, c1, c2, c3, c4), min, max, speeds, source);

    private static RobotModel[] Build()
    {
        Joints urSmall = J(180, 180, 180, 360, 360, 360), urAll180 = J(180, 180, 180, 180, 180, 180);
        Joints urLarge = J(120, 120, 180, 180, 180, 180), urXl = J(120, 120, 150, 210, 210, 210);

        Joints irb1200Min = J(-170, -100, -200, -270, -130, -400), irb1200Max = J(170, 135, 70, 270, 130, 400);
        Joints irb2600Min = J(-180, -95, -180, -400, -120, -400), irb2600Max = J(180, 155, 75, 400, 120, 400);
        Joints irb4600Min = J(-180, -90, -180, -400, -125, -400), irb4600Max = J(180, 150, 75, 400, 120, 400);
        Joints agilusMin = J(-170, -190, -120, -185, -120, -350), agilusMax = J(170, 45, 156, 185, 120, 350);

        return
        [
            Ur("UR3", 151.9, -243.65, -213.25, 112.35, 85.35, 81.9, urSmall),
            Ur("UR5", 89.159, -425, -392.25, 109.15, 94.65, 82.3, urAll180),
            Ur("UR10", 127.3, -612, -572.3, 163.941, 115.7, 92.2, urLarge),
            Ur("UR3e", 151.85, -243.55, -213.2, 131.05, 85.35, 92.1, urSmall),
            Ur("UR5e", 162.5, -425, -392.2, 133.3, 99.7, 99.6, urAll180),
            Ur("UR10e", 180.7, -612.7, -571.55, 174.15, 119.85, 116.55, urLarge),
            Ur("UR16e", 180.7, -478.4, -360, 174.15, 119.85, 116.55, urLarge),
            Ur("UR20", 236.3, -862, -728.7, 201, 159.3, 154.3, urXl),
            Ur("UR30", 236.3, -637, -503.7, 201, 159.3, 154.3, urXl),

            Opw("ABB", "IRB 120", 0, -70, 290, 270, 302, 72, J(-165, -110, -110, -160, -120, -400), J(165, 110, 70, 160, 120, 400), J(250, 250, 250, 320, 320, 420),
                $"{AbbSpec}: IRB 120 (3HAC035960-001)"),
            Opw("ABB", "IRB 140", 70, 0, 352, 360, 380, 65, J(-180, -90, -230, -200, -120, -400), J(180, 110, 50, 200, 120, 400), J(200, 200, 260, 360, 360, 450),
                $"{AbbSpec}: IRB 140 (3HAC041346-001)"),
            Opw("ABB", "IRB 1200-5/0.9", 0, -42, 399, 448, 451, 82, irb1200Min, irb1200Max, J(288, 240, 300, 400, 405, 600),
                $"{AbbSpec}: IRB 1200 (3HAC046982-001)"),
            Opw("ABB", "IRB 1200-7/0.7", 0, -42, 399, 350, 351, 82, irb1200Min, irb1200Max, J(288, 240, 297, 400, 405, 600),
                $"{AbbSpec}: IRB 1200 (3HAC046982-001)"),
            Opw("ABB", "IRB 2600-12/1.65", 150, -115, 445, 700, 795, 85, irb2600Min, irb2600Max, J(175, 175, 175, 360, 360, 510),
                $"{AbbSpec}: IRB 2600 (3HAC035959-001)"),
            Opw("ABB", "IRB 2600-20/1.65", 150, -115, 445, 700, 795, 85, irb2600Min, irb2600Max, J(175, 175, 175, 360, 360, 510),
                $"{AbbSpec}: IRB 2600 (3HAC035959-001)"),
            Opw("ABB", "IRB 4600-60/2.05", 175, -175, 495, 900, 960, 135, irb4600Min, irb4600Max, J(175, 175, 175, 250, 250, 360),
                $"{AbbSpec}: IRB 4600 (3HAC032885-001)"),
            Opw("ABB", "IRB 4600-40/2.55", 175, -175, 495, 1095, 1270, 135, irb4600Min, irb4600Max, J(175, 175, 175, 250, 250, 360),
                $"{AbbSpec}: IRB 4600 (3HAC032885-001)"),
            Opw("ABB", "IRB 6700-200/2.60", 320, -200, 780, 1125, 1142.5, 200, J(-170, -65, -180, -300, -130, -360), J(170, 85, 70, 300, 130, 360), J(110, 110, 110, 190, 150, 210),
                $"{AbbSpec}: IRB 6700 (3HAC044109-001)"),
            RobotModel.FromOpw("IRB 6700-205/2.80", "ABB", new OpwParameters(320, -200, 0, 780, 1280, 1182.5, 200),
                J(-170, -65, -180, -300, -130, -360), J(170, 85, 70, 300, 130, 360), null, $"{AbbSpec}: IRB 6700 (3HAC044109-001); joint speeds not catalogued"),

            Opw("KUKA", "KR 6 R700 sixx", 25, -35, 400, 315, 365, 80, agilusMin, agilusMax, J(360, 300, 360, 381, 388, 615),
                $"{KukaSpec}: KR AGILUS sixx (PF0003/E)"),
            Opw("KUKA", "KR 6 R900 sixx", 25, -35, 400, 455, 420, 80, agilusMin, agilusMax, J(360, 300, 360, 381, 388, 615),
                $"{KukaSpec}: KR AGILUS sixx (PF0003/E)"),
            Opw("KUKA", "KR 10 R1100 sixx", 25, -35, 400, 560, 515, 80, agilusMin, agilusMax, J(300, 225, 225, 381, 311, 492),
                $"{KukaSpec}: KR AGILUS sixx (PF0003/E)"),
            Opw("KUKA", "KR 16", 260, -35, 675, 680, 670, 158, J(-185, -155, -130, -350, -130, -350), J(185, 35, 154, 350, 130, 350), J(156, 156, 156, 335, 355, 647),
                $"{KukaSpec}: KR 16-2 (Spez KR 16-2)"),
            Opw("KUKA", "KR 120 R2500 pro", 350, 41, 675, 1150, 1000, 215, J(-185, -140, -120, -350, -125, -350), J(185, -5, 155, 350, 125, 350), J(136, 130, 120, 292, 258, 284),
                $"{KukaSpec}: KR QUANTEC pro (PF0016/E)"),
        ];
    }
}
