namespace Machina;

/// <summary>Chooses linear or joint motion for the following moves.</summary>
public sealed record ActionMotionMode : RobotAction
{
    /// <summary>Creates a motion-mode action.</summary>
    public ActionMotionMode(MotionType motionType)
    {
        MotionType = EnumText.RequireDefined(motionType, nameof(motionType));
    }

    /// <summary>The new motion type.</summary>
    public MotionType MotionType { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.MotionMode;

    /// <inheritdoc/>
    public override string ToInstruction() => $"MotionMode(\"{MotionType}\");";

    /// <inheritdoc/>
    public override string Describe() => $"Set motion type to '{MotionType}'";
}
