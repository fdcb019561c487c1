namespace Machina;

/// <summary>Shows a message on the robot's teach pendant or screen.</summary>
public sealed record ActionMessage : RobotAction
{
    /// <summary>Creates a message action.</summary>
    public ActionMessage(string message)
    {
        Message = message ?? throw new ArgumentNullException(nameof(message), "A message needs a text (it may be empty).");
    }

    /// <summary>The text to show.</summary>
    public string Message { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Message;

    /// <inheritdoc/>
    public override string ToInstruction() => $"Message({InstructionText.Quote(Message)});";

    /// <inheritdoc/>
    public override string Describe() => $"Display message \"{Message}\"";
}
