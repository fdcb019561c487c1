namespace Machina;

/// <summary>One message from a robot's log.</summary>
/// <param name="Source">Name of the robot that wrote it, or "Machina".</param>
/// <param name="Level">How important it is.</param>
/// <param name="Message">The text.</param>
public sealed record LogEntry(string Source, LogLevel Level, string Message)
{
    /// <summary>
    /// The action this entry reports as refused when it was issued, or null: a program that reports refusals itself (from
    /// <see cref="ActionRefusedException"/>) can tell these entries apart without reading their text.
    /// </summary>
    public RobotAction? Refused { get; init; }

    /// <summary>True when both entries have the same source, level and message (the refused action is not part of an entry's value).</summary>
    public bool Equals(LogEntry? other) =>
        other is not null && Source == other.Source && Level == other.Level && Message == other.Message;

    /// <summary>A hash of the source, level and message.</summary>
    public override int GetHashCode() => HashCode.Combine(Source, Level, Message);

    /// <summary>Text such as <c>HelloRobot VERBOSE: TCP position at [400, 300, 750]</c>.</summary>
    public override string ToString() => $"{Source} {Level}: {Message}";
}
