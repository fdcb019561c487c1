namespace Machina;

/// <summary>Adds a tool to the robot's tool library so that it can be attached by name.</summary>
public sealed record ActionDefineTool : RobotAction
{
    /// <summary>Creates a define-tool action.</summary>
    public ActionDefineTool(Tool tool)
    {
        Tool = tool ?? throw new ArgumentNullException(nameof(tool), "DefineTool needs a tool.");
    }

    /// <summary>The tool to define.</summary>
    public Tool Tool { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.DefineTool;

    /// <inheritdoc/>
    public override string ToInstruction() => Tool.ToDefineInstruction();

    /// <inheritdoc/>
    public override string Describe() => $"Define tool \"{Tool.Name}\" on the Robot.";
}
