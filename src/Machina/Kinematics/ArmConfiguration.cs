namespace Machina;

/// <summary>
/// Which of the (up to eight) ways of reaching one pose the arm uses: three yes/no choices, shoulder, elbow and wrist.
/// See docs/kinematics.md for the exact definition per robot family.
/// </summary>
/// <param name="ShoulderBack">Shoulder: the wrist centre is behind axis 1 (ABB cfx "backward", KUKA Status bit 0 "overhead"); for UR, the second shoulder solution.</param>
/// <param name="ElbowDown">Elbow: the wrist centre is behind the lower-arm line (ABB cfx "backward", KUKA Status bit 1 = 0); for UR, J3 &gt; 0.</param>
/// <param name="WristFlipped">Wrist: axis 5 is negative.</param>
public readonly record struct ArmConfiguration(bool ShoulderBack, bool ElbowDown, bool WristFlipped)
{
    /// <summary>A number 0..7: 4 × shoulder + 2 × elbow + wrist (the same numbering as ABB's cfx).</summary>
    public int Index => (ShoulderBack ? 4 : 0) + (ElbowDown ? 2 : 0) + (WristFlipped ? 1 : 0);

    /// <summary>The configuration with the given <see cref="Index"/> 0..7.</summary>
    public static ArmConfiguration FromIndex(int index)
    {
        if (index is < 0 or > 7)
        {
            throw new ArgumentOutOfRangeException(nameof(index), index, "An arm configuration index is 0 to 7.");
        }
        return new ArmConfiguration((index & 4) != 0, (index & 2) != 0, (index & 1) != 0);
    }

    /// <summary>Text such as <c>shoulder front, elbow up, wrist not flipped</c>.</summary>
    public override string ToString() =>
        $"shoulder {(ShoulderBack ? "back" : "front")}, elbow {(ElbowDown ? "down" : "up")}, wrist {(WristFlipped ? "flipped" : "not flipped")}";
}
