namespace Machina;

/// <summary>Attaches a tool defined earlier with <c>DefineTool</c>: from now on positions refer to the tool's tip.</summary>
public sealed record ActionAttachTool : RobotAction
{
    /// <summary>Creates an attach action for the tool named <paramref name="toolName"/>.</summary>
    public ActionAttachTool(string toolName)
    {
        ToolName = Tool.ValidateName(toolName);
    }

    /// <summary>Name of the tool to attach.</summary>
    public string ToolName { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.AttachTool;

    /// <inheritdoc/>
    public override string ToInstruction() => $"AttachTool({InstructionText.Quote(ToolName)});";

    /// <inheritdoc/>
    public override string Describe() => $"Attach tool \"{ToolName}\" to robot flange.";
}
