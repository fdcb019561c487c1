namespace Machina;

/// <summary>Adds a comment to the compiled program; the robot does nothing.</summary>
public sealed record ActionComment : RobotAction
{
    /// <summary>Creates a comment action.</summary>
    public ActionComment(string comment)
    {
        Comment = comment ?? throw new ArgumentNullException(nameof(comment), "A comment needs a text (it may be empty).");
    }

    /// <summary>The comment text.</summary>
    public string Comment { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Comment;

    /// <inheritdoc/>
    public override string ToInstruction() => $"Comment({InstructionText.Quote(Comment)});";

    /// <inheritdoc/>
    public override string Describe() => $"Comment: \"{Comment}\"";
}
