using System.Collections.Concurrent;

namespace Machina;

/// <summary>
/// The session's one loop: every change to its state (the buffer, the cursors, the in-flight list, the connection state) is a
/// message handled here, one at a time, in the order posted. Messages are issued actions, driver reports, watchdog ticks
/// and the robot's calls (connect, disconnect, resume, clear, wait, queries). The loop is a serialised executor with no
/// thread of its own: whoever posts while it is idle runs it until the mailbox is empty, the others only post and leave.
/// So an action issued while nothing else happens is released before <c>Move</c> returns (as before), and no thread ever
/// waits for the loop except a caller asking it a question. The loop never runs user code (handlers and log sinks run on
/// the <see cref="EventPump"/>) and never waits except for the robot's issue lock (<see cref="IOnlineHost.WithIssueCursor"/>);
/// so nobody may ask the loop a question while holding the issue lock.
/// </summary>
internal sealed partial class OnlineSession
{
    private readonly ConcurrentQueue<Action> _mailbox = new();

    /// <summary>Actions issued and not moved into <see cref="_buffer"/> yet: the robot adds them under its issue lock.</summary>
    private readonly ConcurrentQueue<Pending> _inbox = new();

    /// <summary>The managed thread id of the thread running the loop, 0 while it is idle.</summary>
    private int _owner;

    /// <summary>Posts a message; runs the loop on this thread when it is idle.</summary>
    private void Post(Action message)
    {
        _mailbox.Enqueue(message);
        Run();
    }

    private void Run()
    {
        int me = Environment.CurrentManagedThreadId;
        while (Interlocked.CompareExchange(ref _owner, me, 0) == 0)
        {
            while (_mailbox.TryDequeue(out Action? message))
            {
                try
                {
                    TakeIssued();
                    message();
                }
                catch (Exception ex)
                {
                    // A bug, never a report: say so and keep the loop alive for the next message.
                    Log(LogLevel.ERROR, $"The online session of \"{_host.Name}\" failed handling a message: {ex.GetType().Name}: {ex.Message}");
                }
            }
            Volatile.Write(ref _owner, 0);
            if (_mailbox.IsEmpty)
            {
                return;
            }
        }
    }

    /// <summary>True on the thread running the loop now.</summary>
    private bool IsOnLoop => Volatile.Read(ref _owner) == Environment.CurrentManagedThreadId;

    /// <summary>Asks the loop a question and waits for the answer (at once when this thread runs or can run the loop).</summary>
    private T Ask<T>(Func<T> question)
    {
        if (IsOnLoop)
        {
            return question();
        }
        return AskAsync(question).GetAwaiter().GetResult();
    }

    /// <summary>Asks the loop a question; the task completes with the answer, or fails with what the question threw.</summary>
    private Task<TAnswer> AskAsync<TAnswer>(Func<TAnswer> question)
    {
        var answer = new TaskCompletionSource<TAnswer>(TaskCreationOptions.RunContinuationsAsynchronously);
        Post(() =>
        {
            try
            {
                answer.TrySetResult(question());
            }
            catch (Exception ex)
            {
                answer.TrySetException(ex);
            }
        });
        return answer.Task;
    }

    /// <summary>Moves the issued actions into the buffer, in issue order (on the loop; under the issue lock it takes them all).</summary>
    private void TakeIssued()
    {
        while (_inbox.TryDequeue(out Pending pending))
        {
            _buffer.Enqueue(pending);
        }
    }

    /// <summary>Runs <paramref name="change"/> on the loop under the robot's issue lock, with every issued action in the buffer.</summary>
    private void WithIssueCursor(Action<RobotCursor> change)
    {
        IReadOnlyList<(LogLevel Level, string Message)>? lines = _host.WithIssueCursor(issue =>
        {
            TakeIssued();
            change(issue);
        });
        foreach ((LogLevel level, string message) in lines ?? [])
        {
            Log(level, message);
        }
    }
}
