namespace Machina;

/// <summary>Turns the 3D printer's extrusion on or off for the following moves.</summary>
public sealed record ActionExtrusion : RobotAction
{
    /// <summary>Creates an extrusion on (true) or off (false) action.</summary>
    public ActionExtrusion(bool extrude) => Extrude = extrude;

    /// <summary>True to extrude while moving.</summary>
    public bool Extrude { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Extrusion;

    /// <inheritdoc/>
    public override string ToInstruction() => $"Extrude({InstructionText.Bool(Extrude)});";

    /// <inheritdoc/>
    public override string Describe() => Extrude ? "Turn extrusion on" : "Turn extrusion off";
}
