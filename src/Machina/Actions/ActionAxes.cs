namespace Machina;

/// <summary>Turns the robot's joints to given angles (<c>AxesTo</c>) or by given amounts (<c>Axes</c>), in degrees.</summary>
public sealed record ActionAxes : RobotAction
{
    /// <summary>Creates a joint motion; values in degrees.</summary>
    public ActionAxes(Joints joints, bool relative)
    {
        Joints = joints.RequireFinite(nameof(joints));
        Relative = relative;
    }

    /// <summary>The target joint angles (absolute) or their changes (relative), degrees.</summary>
    public Joints Joints { get; }

    /// <summary>True for changes, false for target angles.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Axes;

    /// <inheritdoc/>
    public override string ToInstruction()
    {
        Joints j = Joints;
        return InstructionText.Call(Relative ? "Axes" : "AxesTo", j.J1, j.J2, j.J3, j.J4, j.J5, j.J6);
    }

    /// <inheritdoc/>
    public override string Describe() => Relative ? $"Increase joint rotations by {Joints} deg" : $"Set joint rotations to {Joints} deg";
}
