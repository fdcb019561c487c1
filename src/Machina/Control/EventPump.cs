using System.Threading.Channels;

namespace Machina;

/// <summary>
/// Raises a connection's events one at a time, in the order they happened, on one background loop: the link's own loops
/// never run user code, a slow handler never delays the robot, and a handler may issue actions without deadlocks.
/// </summary>
internal sealed class EventPump
{
    private readonly Channel<Item> _queue = Channel.CreateUnbounded<Item>(new UnboundedChannelOptions { SingleReader = true });
    private readonly Action<MachinaEventArgs> _raise;
    private readonly Task _loop;
    private int _raisingThread = -1;
    private volatile bool _dropping;

    /// <summary>Starts the loop; <paramref name="raise"/> delivers one event to its subscribers and must not throw.</summary>
    internal EventPump(Action<MachinaEventArgs> raise)
    {
        _raise = raise;
        _loop = Task.Run(RunAsync);
    }

    /// <summary>True when called from inside an event handler run by this pump.</summary>
    internal bool IsRaisingOnCurrentThread => Volatile.Read(ref _raisingThread) == Environment.CurrentManagedThreadId;

    /// <summary>Queues an event.</summary>
    internal void Post(MachinaEventArgs args) => _queue.Writer.TryWrite(new Item(args, null, null, null));

    /// <summary>Completes (or fails, when <paramref name="error"/> is set) a waiting task after every event queued so far was raised.</summary>
    internal void PostSignal(TaskCompletionSource signal, Exception? error) => _queue.Writer.TryWrite(new Item(null, signal, error, null));

    /// <summary>Queues a log entry: the log's sinks and handlers run on this loop, in order with the events (dropped once stopped).</summary>
    internal void PostLog(RobotLogger logger, LogLevel level, string message)
    {
        if (logger.IsEnabled(level))
        {
            _queue.Writer.TryWrite(new Item(null, null, null, new LogLine(logger, level, message)));
        }
    }

    /// <summary>
    /// Stops the loop after raising what is queued (<paramref name="raiseQueued"/>) or after the handler running now (the
    /// queued events are dropped and waiting tasks are cancelled). Completes when no handler of this pump runs any more; called
    /// from inside a handler it cannot wait for that and completes at once.
    /// </summary>
    internal Task StopAsync(bool raiseQueued)
    {
        _dropping |= !raiseQueued;
        _queue.Writer.TryComplete();
        return IsRaisingOnCurrentThread ? Task.CompletedTask : _loop;
    }

    private async Task RunAsync()
    {
        await foreach (Item item in _queue.Reader.ReadAllAsync().ConfigureAwait(false))
        {
            if (_dropping)
            {
                item.Signal?.TrySetCanceled();
            }
            else if (item.Log is { } line)
            {
                Volatile.Write(ref _raisingThread, Environment.CurrentManagedThreadId);
                line.Logger.Write(line.Level, line.Message);
                Volatile.Write(ref _raisingThread, -1);
            }
            else if (item.Args is not null)
            {
                Volatile.Write(ref _raisingThread, Environment.CurrentManagedThreadId);
                _raise(item.Args);
                Volatile.Write(ref _raisingThread, -1);
            }
            else if (item.Error is null)
            {
                item.Signal!.TrySetResult();
            }
            else
            {
                item.Signal!.TrySetException(item.Error);
            }
        }
    }

    private readonly record struct Item(MachinaEventArgs? Args, TaskCompletionSource? Signal, Exception? Error, LogLine? Log);

    private sealed record LogLine(RobotLogger Logger, LogLevel Level, string Message);
}
