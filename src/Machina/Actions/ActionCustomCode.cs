namespace Machina;

/// <summary>Inserts a line of the robot's own language into the program as it is (for experts: Machina cannot check it).</summary>
public sealed record ActionCustomCode : RobotAction
{
    /// <summary>Creates a custom-code action; declarations go to the program's declaration block.</summary>
    public ActionCustomCode(string statement, bool isDeclaration)
    {
        Statement = statement ?? throw new ArgumentNullException(nameof(statement), "Custom code needs a statement.");
        if (statement.Contains('\n') || statement.Contains('\r'))
        {
            throw new ArgumentException("Custom code must be a single line; issue one CustomCode per line.", nameof(statement));
        }
        IsDeclaration = isDeclaration;
    }

    /// <summary>The native code line.</summary>
    public string Statement { get; }

    /// <summary>True when the line declares something and belongs to the declarations block.</summary>
    public bool IsDeclaration { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.CustomCode;

    /// <inheritdoc/>
    public override string ToInstruction() => $"CustomCode({InstructionText.Quote(Statement)},{InstructionText.Bool(IsDeclaration)});";

    /// <inheritdoc/>
    public override string Describe() => IsDeclaration ? $"Add custom declaration: \"{Statement}\"" : $"Add custom instruction: \"{Statement}\"";
}
