namespace Machina;

/// <summary>Chooses the frame (world or tool) in which the following relative actions are expressed.</summary>
public sealed record ActionCoordinates : RobotAction
{
    /// <summary>Creates a reference-frame action.</summary>
    public ActionCoordinates(ReferenceCS referenceCS)
    {
        ReferenceCS = EnumText.RequireDefined(referenceCS, nameof(referenceCS));
    }

    /// <summary>The new reference frame.</summary>
    public ReferenceCS ReferenceCS { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Coordinates;

    /// <inheritdoc/>
    public override string ToInstruction() => $"Coordinates(\"{ReferenceCS}\");";

    /// <inheritdoc/>
    public override string Describe() => $"Set reference coordinate system to '{ReferenceCS}'";
}
