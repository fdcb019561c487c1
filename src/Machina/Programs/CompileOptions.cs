namespace Machina;

/// <summary>How <c>Robot.Compile</c> writes a program.</summary>
public sealed record CompileOptions
{
    /// <summary>Write each target inside its motion instruction (true, default) or declare it first as a named variable (false).</summary>
    public bool InlineTargets { get; init; } = true;

    /// <summary>Append a human-readable description of each action as a comment to its line (default true).</summary>
    public bool HumanComments { get; init; } = true;

    /// <summary>When set, the header states this creation time; by default programs carry no date so that compiling is repeatable.</summary>
    public DateTimeOffset? Timestamp { get; init; }

    /// <summary>The default options.</summary>
    public static CompileOptions Default { get; } = new();
}
