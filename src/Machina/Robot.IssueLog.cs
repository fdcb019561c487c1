using System.Runtime.CompilerServices;

namespace Machina;

public sealed partial class Robot
{
    /// <summary>Log lines written while the issue lock is held, kept until it is released (guarded by the issue lock).</summary>
    private List<(LogLevel Level, string Message, RobotAction? Refused)>? _lockedLog;

    /// <summary>
    /// Logs from under the issue lock: the line is kept and written once the lock is released (by <see cref="UnderIssueLock"/>
    /// on the calling thread, or by the online session on its event pump), so log sinks, which are user code, never run
    /// under the lock.
    /// </summary>
    /// <param name="level">The line's level.</param>
    /// <param name="message">The line.</param>
    /// <param name="refused">The action the line reports as refused, if any (marked on the entry: <see cref="LogEntry.Refused"/>).</param>
    private void LogLocked(LogLevel level, string message, RobotAction? refused = null)
    {
        if (Logger.IsEnabled(level))
        {
            (_lockedLog ??= []).Add((level, message, refused));
        }
    }

    /// <summary>Takes the lines logged under the issue lock (the caller holds it).</summary>
    private List<(LogLevel Level, string Message, RobotAction? Refused)>? TakeLockedLog()
    {
        List<(LogLevel Level, string Message, RobotAction? Refused)>? lines = _lockedLog;
        _lockedLog = null;
        return lines;
    }

    /// <summary>Runs <paramref name="work"/> under the issue lock, then writes what it logged, after the lock is released (also when it throws).</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private TResult UnderIssueLock<TState, TResult>(TState state, Func<Robot, TState, TResult> work)
    {
        List<(LogLevel Level, string Message, RobotAction? Refused)>? lines = null;
        try
        {
            lock (_issueLock)
            {
                try
                {
                    return work(this, state);
                }
                finally
                {
                    lines = TakeLockedLog();
                }
            }
        }
        finally
        {
            // Most issues log nothing: no empty list is made for them (`lines ?? []` made one per action).
            if (lines is not null)
            {
                WriteLockedLog(lines);
            }
        }
    }

    /// <summary>Writes lines taken from under the issue lock, in order.</summary>
    private void WriteLockedLog(List<(LogLevel Level, string Message, RobotAction? Refused)> lines)
    {
        foreach ((LogLevel level, string message, RobotAction? refused) in lines)
        {
            if (refused is not null)
            {
                Logger.Refused(refused, message);
            }
            else
            {
                Logger.Write(level, message);
            }
        }
    }
}
