namespace Machina;

/// <summary>
/// One out-of-band command at a time (stop, pause, resume) and the answer code it waits for: a driver posts the command and
/// its reader hands every answer code to <see cref="Answer"/>. Each brand says how a command is sent and an answer looks.
/// </summary>
internal sealed class ControlExchange(TimeProvider time, TimeSpan timeout)
{
    private readonly object _gate = new();
    private (int Expected, TaskCompletionSource Done)? _pending;

    /// <summary>How long the controller has to answer a command.</summary>
    public TimeSpan Timeout => timeout;

    /// <summary>
    /// Sends a command with <paramref name="post"/> and waits until the answer <paramref name="answer"/> arrives; a
    /// <see cref="RobotStoppedException"/> with <paramref name="timedOut"/> when none comes within <see cref="Timeout"/>.
    /// </summary>
    public async Task RunAsync(Action post, int answer, string what, string timedOut, CancellationToken cancellationToken)
    {
        var done = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        lock (_gate)
        {
            if (_pending is not null)
            {
                throw new InvalidOperationException($"Cannot {what} now: the controller has not answered the command before it yet.");
            }
            _pending = (answer, done);
        }
        try
        {
            post();
            await done.Task.WaitAsync(timeout, time, cancellationToken).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            throw new RobotStoppedException(timedOut);
        }
        finally
        {
            lock (_gate)
            {
                _pending = null;
            }
        }
    }

    /// <summary>
    /// The link the answer would come on was closed: a command still waiting fails now with a <see cref="RobotConnectionException"/>
    /// saying so, instead of at the end of <see cref="Timeout"/> (no answer can arrive any more).
    /// </summary>
    public void Abandon(string controller)
    {
        TaskCompletionSource? waiter;
        lock (_gate)
        {
            waiter = _pending?.Done;
        }
        waiter?.TrySetException(new RobotConnectionException($"The link to the {controller} was closed before it answered the command."));
    }

    /// <summary>An answer code from the controller: completes the command waiting for it (true), or false when none waits for this code.</summary>
    public bool Answer(int code)
    {
        TaskCompletionSource? waiter = null;
        lock (_gate)
        {
            if (_pending is (int expected, TaskCompletionSource done) && expected == code)
            {
                waiter = done;
            }
        }
        return waiter?.TrySetResult() ?? false;
    }
}
