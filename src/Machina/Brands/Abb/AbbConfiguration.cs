namespace Machina;

/// <summary>
/// ABB RAPID <c>confdata</c> [cf1, cf4, cf6, cfx]: the quadrants of axes 1, 4 and 6 (0 = 0°..90°, 1 = 90°..180°, −1 = −90°..0°, …)
/// and cfx 0..7 = 4 × (wrist centre behind axis 1) + 2 × (wrist centre behind the lower arm) + (axis 5 negative).
/// </summary>
/// <param name="Cf1">Quadrant of axis 1.</param>
/// <param name="Cf4">Quadrant of axis 4.</param>
/// <param name="Cf6">Quadrant of axis 6.</param>
/// <param name="Cfx">Arm configuration number 0..7.</param>
public readonly record struct AbbConfiguration(int Cf1, int Cf4, int Cf6, int Cfx)
{
    /// <summary>The confdata of a joint set of <paramref name="model"/> (any brand's geometry; meaningful for ABB arms).</summary>
    public static AbbConfiguration From(RobotModel model, Joints joints)
    {
        ArgumentNullException.ThrowIfNull(model);
        joints.RequireFinite(nameof(joints));
        ArmConfiguration c = model.Kinematics.ConfigurationOf(joints);
        return new AbbConfiguration(Quadrant(joints.J1), Quadrant(joints.J4), Quadrant(joints.J6), c.Index);
    }

    /// <summary>The quadrant number ABB uses: floor(angle / 90°).</summary>
    public static int Quadrant(double degrees) => (int)Math.Floor(degrees / 90.0 + 1e-12);

    /// <summary>RAPID text such as <c>[0,-1,0,0]</c>.</summary>
    public string ToRapid() => $"[{Num.I(Cf1)},{Num.I(Cf4)},{Num.I(Cf6)},{Num.I(Cfx)}]";

    /// <summary>Same as <see cref="ToRapid"/>.</summary>
    public override string ToString() => ToRapid();
}
