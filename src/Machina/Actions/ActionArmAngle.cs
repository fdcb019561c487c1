namespace Machina;

/// <summary>Sets (<c>ArmAngleTo</c>) or changes (<c>ArmAngle</c>) the arm angle of a 7-axis arm (e.g. ABB YuMi), in degrees.</summary>
public sealed record ActionArmAngle : RobotAction
{
    /// <summary>Creates an arm-angle action, degrees.</summary>
    public ActionArmAngle(double angle, bool relative)
    {
        Angle = Num.Finite(angle, nameof(angle));
        Relative = relative;
    }

    /// <summary>The angle (absolute) or its change (relative), degrees.</summary>
    public double Angle { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.ArmAngle;

    /// <inheritdoc/>
    public override string ToInstruction() => InstructionText.Call(Relative ? "ArmAngle" : "ArmAngleTo", Angle);

    /// <inheritdoc/>
    public override string Describe() => Relative
        ? $"{InstructionText.Change(Angle)} arm-angle by {Num.G(Angle)} deg"
        : $"Set arm-angle to {Num.G(Angle)} deg";
}
