namespace Machina;

/// <summary>
/// KUKA Status and Turn of a Cartesian point (KRL <c>S</c> and <c>T</c>). Status bit 0: wrist point behind axis 1 (overhead area);
/// bit 1: A3 at or beyond the stretched-arm angle φ (wrist point in front of the lower arm); bit 2: A5 &lt; 0 (hand flip).
/// Turn bit n (0..5) is set when axis n+1 is negative (beyond rounding noise, <see cref="ZeroTolerance"/>).
/// </summary>
/// <param name="Status">Status bits 0..7.</param>
/// <param name="Turn">Turn bits 0..63.</param>
public readonly record struct KukaConfiguration(int Status, int Turn)
{
    /// <summary>The Status and Turn of a joint set of <paramref name="model"/> (any brand's geometry; meaningful for KUKA arms).</summary>
    public static KukaConfiguration From(RobotModel model, Joints joints)
    {
        ArgumentNullException.ThrowIfNull(model);
        joints.RequireFinite(nameof(joints));
        ArmConfiguration c = model.Kinematics.ConfigurationOf(joints);
        int status = (c.ShoulderBack ? 1 : 0) | (c.ElbowDown ? 0 : 2) | (joints.J5 < -ZeroTolerance ? 4 : 0);
        int turn = 0;
        for (int i = 0; i < Joints.Count; i++)
        {
            if (joints[i] < -ZeroTolerance)
            {
                turn |= 1 << i;
            }
        }
        return new KukaConfiguration(status, turn);
    }

    /// <summary>
    /// How close to 0° an axis counts as 0 (not negative), degrees: the inverse kinematics leaves noise such as -1e-14° on an
    /// axis that is at 0, and a Turn bit must not depend on it (or a target written from one solution names no other).
    /// </summary>
    internal const double ZeroTolerance = 1e-9;

    /// <summary>Status as KRL binary text, e.g. <c>'B010'</c>.</summary>
    public string StatusText => $"'B{Convert.ToString(Status, 2).PadLeft(3, '0')}'";

    /// <summary>Turn as KRL binary text, e.g. <c>'B000010'</c>.</summary>
    public string TurnText => $"'B{Convert.ToString(Turn, 2).PadLeft(6, '0')}'";

    /// <summary>The fragment for a KRL E6POS aggregate, e.g. <c>S 'B010',T 'B000010'</c>.</summary>
    public string ToKrl() => $"S {StatusText},T {TurnText}";

    /// <summary>Text such as <c>S 'B010' T 'B000010'</c>.</summary>
    public override string ToString() => $"S {StatusText} T {TurnText}";
}
