namespace Machina;

/// <summary>Detaches the current tool: positions refer to the robot's flange again.</summary>
public sealed record ActionDetachTool : RobotAction
{
    /// <inheritdoc/>
    public override ActionType Type => ActionType.DetachTool;

    /// <inheritdoc/>
    public override string ToInstruction() => "DetachTool();";

    /// <inheritdoc/>
    public override string Describe() => "Detach all tools from robot.";
}
