namespace Machina;

/// <summary>Runs the device's start-up (<c>Initialize</c>) or shut-down (<c>Terminate</c>) sequence, e.g. homing and heating a 3D printer.</summary>
public sealed record ActionInitialization : RobotAction
{
    /// <summary>Creates a start-up (true) or shut-down (false) action.</summary>
    public ActionInitialization(bool initialize) => Initialize = initialize;

    /// <summary>True for start-up, false for shut-down.</summary>
    public bool Initialize { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Initialization;

    /// <inheritdoc/>
    public override string ToInstruction() => Initialize ? "Initialize();" : "Terminate();";

    /// <inheritdoc/>
    public override string Describe() => Initialize ? "Initialize this device." : "Terminate this device.";
}
