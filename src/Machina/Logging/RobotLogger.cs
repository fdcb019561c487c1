namespace Machina;

/// <summary>
/// A robot's own log. Subscribe to <see cref="Logged"/> (or set <see cref="Writer"/>) to see its messages; <see cref="Level"/>
/// chooses how much is reported. Machina itself never writes to the console.
/// </summary>
public sealed class RobotLogger
{
    private readonly string _source;

    internal RobotLogger(string source) => _source = source;

    /// <summary>Messages up to this level are reported (default <see cref="LogLevel.INFO"/>).</summary>
    public LogLevel Level { get; set; } = LogLevel.INFO;

    /// <summary>Raised for every reported message, on the thread that wrote it.</summary>
    public event EventHandler<LogEntry>? Logged;

    /// <summary>When set, every reported message is also written to it as one line.</summary>
    public TextWriter? Writer { get; set; }

    /// <summary>True when a message of <paramref name="level"/> would be reported; check it before building costly texts.</summary>
    public bool IsEnabled(LogLevel level) => level != LogLevel.NONE && level <= Level && (Logged is not null || Writer is not null);

    /// <summary>Reports an error.</summary>
    public void Error(string message) => Write(LogLevel.ERROR, message);

    /// <summary>Reports a warning.</summary>
    public void Warning(string message) => Write(LogLevel.WARNING, message);

    /// <summary>Reports information.</summary>
    public void Info(string message) => Write(LogLevel.INFO, message);

    /// <summary>Reports a detail.</summary>
    public void Verbose(string message) => Write(LogLevel.VERBOSE, message);

    /// <summary>Reports debugging information.</summary>
    public void Debug(string message) => Write(LogLevel.DEBUG, message);

    /// <summary>Reports a message at a level.</summary>
    public void Write(LogLevel level, string message)
    {
        if (!IsEnabled(level))
        {
            return;
        }
        var entry = new LogEntry(_source, level, message);
        try
        {
            Logged?.Invoke(this, entry);
            Writer?.WriteLine(entry.ToString());
        }
        catch (Exception)
        {
            // A failing log subscriber must never stop the robot.
        }
    }
}
