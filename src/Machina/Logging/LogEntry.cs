namespace Machina;

/// <summary>One message from a robot's log.</summary>
/// <param name="Source">Name of the robot that wrote it, or "Machina".</param>
/// <param name="Level">How important it is.</param>
/// <param name="Message">The text.</param>
public sealed record LogEntry(string Source, LogLevel Level, string Message)
{
    /// <summary>Text such as <c>HelloRobot VERBOSE: TCP position at [400, 300, 750]</c>.</summary>
    public override string ToString() => $"{Source} {Level}: {Message}";
}
