using System.Runtime.CompilerServices;
using System.Collections.Immutable;

namespace Machina;

/// <summary>
/// A robot's own log. Subscribe to <see cref="Logged"/> (or set <see cref="Writer"/>) to see its messages; <see cref="Level"/>
/// chooses how much is reported. A host routes the log to its own logger with one call to
/// <see cref="AddSink(Action{LogEntry}, LogLevel)"/>. Machina itself never writes to the console.
/// </summary>
public sealed class RobotLogger
{
    private readonly string _source;
    private ImmutableArray<Sink> _sinks = ImmutableArray<Sink>.Empty;

    internal RobotLogger(string source) => _source = source;

    /// <summary>The log a forwarding logger writes to, or null (see the constructor taking a target).</summary>
    private readonly RobotLogger? _target;

    /// <summary>What a forwarding logger does with a line its target wants.</summary>
    private readonly Action<LogLevel, string>? _forward;

    /// <summary>
    /// A logger that hands every line <paramref name="target"/> wants to <paramref name="forward"/> instead of writing it (the
    /// online session gives one to its device drivers, to write their lines on the robot's event pump).
    /// </summary>
    internal RobotLogger(RobotLogger target, Action<LogLevel, string> forward)
        : this(target._source)
    {
        _target = target;
        _forward = forward;
    }

    /// <summary>Messages up to this level are reported (default <see cref="LogLevel.INFO"/>).</summary>
    public LogLevel Level { get; set; } = LogLevel.INFO;

    /// <summary>Raised for every reported message, on the thread that wrote it.</summary>
    public event EventHandler<LogEntry>? Logged;

    /// <summary>When set, every reported message is also written to it as one line.</summary>
    public TextWriter? Writer { get; set; }

    /// <summary>True when a message of <paramref name="level"/> would be reported; check it before building costly texts.</summary>
    public bool IsEnabled(LogLevel level) => _target is not null ? _target.IsEnabled(level) :
        level != LogLevel.NONE && ((level <= Level && (Logged is not null || Writer is not null)) || AnySinkWants(level));

    /// <summary>
    /// Sends every message of this robot up to <paramref name="level"/> to <paramref name="sink"/>, for example your
    /// application's logger: <c>bot.Logger.AddSink(e => log.Log(Map(e.Level), "{Robot}: {Text}", e.Source, e.Message))</c>.
    /// Each sink has its own level (<see cref="Level"/> applies only to <see cref="Logged"/> and <see cref="Writer"/>).
    /// The sink is called on the thread that wrote the message; if it throws, the robot carries on.
    /// Dispose the result to stop.
    /// </summary>
    public IDisposable AddSink(Action<LogEntry> sink, LogLevel level = LogLevel.INFO)
    {
        ArgumentNullException.ThrowIfNull(sink);
        if (level < LogLevel.NONE || level > LogLevel.DEBUG)
        {
            throw new ArgumentOutOfRangeException(nameof(level), level, "The level must be one of LogLevel's values, from NONE to DEBUG.");
        }
        var added = new Sink(this, sink, level);
        ImmutableInterlocked.Update(ref _sinks, (sinks, s) => sinks.Add(s), added);
        return added;
    }

    /// <summary>
    /// Writes every message of this robot up to <paramref name="level"/> to <paramref name="writer"/> as one line, such as
    /// <c>HelloRobot WARNING: …</c>. If several threads log, give a thread-safe writer (<see cref="TextWriter.Synchronized"/>).
    /// Dispose the result to stop.
    /// </summary>
    public IDisposable AddSink(TextWriter writer, LogLevel level = LogLevel.INFO)
    {
        ArgumentNullException.ThrowIfNull(writer);
        return AddSink(entry => writer.WriteLine(entry.ToString()), level);
    }

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
        if (_forward is not null)
        {
            _forward(level, message);
            return;
        }
        Write(new LogEntry(_source, level, message));
    }

    /// <summary>Reports, as a warning, an action refused when it was issued (the entry's <see cref="LogEntry.Refused"/> is the action).</summary>
    internal void Refused(RobotAction action, string message)
    {
        if (IsEnabled(LogLevel.WARNING))
        {
            Write(new LogEntry(_source, LogLevel.WARNING, message) { Refused = action });
        }
    }

    private void Write(LogEntry entry)
    {
        LogLevel level = entry.Level;
        if (level <= Level)
        {
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
        foreach (Sink sink in _sinks)
        {
            if (level <= sink.Level)
            {
                try
                {
                    sink.Receive(entry);
                }
                catch (Exception)
                {
                    // Nor a failing sink; the other sinks still receive the entry.
                }
            }
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private bool AnySinkWants(LogLevel level)
    {
        foreach (Sink sink in _sinks)
        {
            if (level <= sink.Level)
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>One sink added by a host; disposing it removes it.</summary>
    private sealed class Sink(RobotLogger owner, Action<LogEntry> receive, LogLevel level) : IDisposable
    {
        public LogLevel Level { get; } = level;

        public Action<LogEntry> Receive { get; } = receive;

        public void Dispose() => ImmutableInterlocked.Update(ref owner._sinks, (sinks, s) => sinks.Remove(s), this);
    }
}
