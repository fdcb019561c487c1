namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>The reason of an action stopped by <see cref="StopAsync"/>, and of every action cancelled after it.</summary>
    internal const string StoppedByUser = "stopped by the user (Robot.Stop): the motion stopped where the arm was and nothing after it ran.";

    /// <summary>The code of <see cref="StoppedByUser"/> in <see cref="ActionFailedException.ControllerCode"/>.</summary>
    internal const string StoppedCode = "stopped";

    /// <summary>The link whose program the user stopped: a failure it reports is the stop (<see cref="StoppedByUser"/>).</summary>
    private Connection? _stoppedByUser;

    /// <summary>
    /// Completed (on the loop) once the controller's own report ended the link the user stopped (<see cref="StopApplied"/>): the
    /// link is closed then, so the answer to the stop command may never be read, and <see cref="StopAsync"/> no longer waits for it.
    /// </summary>
    private TaskCompletionSource? _stopApplied;

    /// <summary>
    /// Holds the motion on the controller (out of band) and stops releasing: the state becomes Stopped with the reason
    /// "paused by the user" until <see cref="ResumeAsync"/>.
    /// </summary>
    internal async Task PauseAsync(CancellationToken cancellationToken)
    {
        Connection link = await AskAsync(() => _state == ConnectionState.Stopped
            ? throw new InvalidOperationException($"The robot is already stopped ({_stopReason!.Message}); call Resume to go on.")
            : RequireLink("pause")).ConfigureAwait(false);
        await link.Driver.PauseAsync(cancellationToken).ConfigureAwait(false);
        await AskAsync(() =>
        {
            OnStopped(link, new RobotStoppedException("Paused by the user (Robot.Pause): the motion holds where the arm is; call Resume to go on.", "pause"), byUser: true);
            return true;
        }).ConfigureAwait(false);
    }

    /// <summary>
    /// Stops the motion on the controller now (out of band), then fails the action it was running and cancels every action
    /// after it, sent or not (<c>ActionFailed</c>, reason <see cref="StoppedByUser"/>); the link is closed.
    /// </summary>
    /// <remarks>
    /// The controller may report the stopped program (ABB: the driver's <c>$26 id 4;</c>) before its answer to the stop command
    /// (the monitor's <c>$28 3;</c>) is read: that report is applied as the stop and closes the link, and the answer then never
    /// arrives. The stop is done at that point, so this returns then instead of waiting for the answer until the command times out.
    /// </remarks>
    internal async Task StopAsync(CancellationToken cancellationToken)
    {
        (Connection link, Task applied) = await AskAsync(() =>
        {
            Connection current = RequireLink("stop");
            _stoppedByUser = current;
            _stopApplied = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            return (current, _stopApplied.Task);
        }).ConfigureAwait(false);
        try
        {
            Task answered = link.Driver.StopMotionAsync(cancellationToken);
            await Task.WhenAny(answered, applied).ConfigureAwait(false);
            // Closing the link fails the wait for the answer (it cannot come any more) in the same turn of the loop that applied the
            // report: asked on the loop, that turn has ended, so whether the stop was applied is known.
            if (!answered.IsCompletedSuccessfully && (applied.IsCompleted || await AskAsync(() => applied.IsCompleted).ConfigureAwait(false)))
            {
                // Applied from the controller's report; the answer, now unreadable, is still observed when its wait ends.
                _ = answered.ContinueWith(static t => t.Exception, CancellationToken.None, TaskContinuationOptions.OnlyOnFaulted, TaskScheduler.Default);
                return;
            }
            await answered.ConfigureAwait(false);
        }
        catch
        {
            await AskAsync(() => (_stoppedByUser, _stopApplied) = (null, null)).ConfigureAwait(false);
            throw;
        }
        await AskAsync(() =>
        {
            WithIssueCursor(issue => StopPending(link, issue));
            return true;
        }).ConfigureAwait(false);
    }

    private Connection RequireLink(string what)
    {
        if (_disposed)
        {
            throw Disposed(what);
        }
        return _link ?? throw new InvalidOperationException($"Cannot {what}: the robot is not connected to a controller.");
    }

    /// <summary>
    /// The controller's report (a failure, or the link closing) ended the link the user stopped and was applied as the stop (on the
    /// loop): a <see cref="StopAsync"/> waiting for the answer to its command returns.
    /// </summary>
    private void StopApplied(Connection link)
    {
        if (ReferenceEquals(_stoppedByUser, link) && !ReferenceEquals(_link, link))
        {
            _stopApplied?.TrySetResult();
        }
    }

    /// <summary>After the controller stopped: everything not executed is abandoned (unless its failure report did it already).</summary>
    private void StopPending(Connection link, RobotCursor issue)
    {
        if (!ReferenceEquals(_link, link))
        {
            return;   // the controller's own report of the stopped program came first and was applied as the stop
        }
        var pending = new List<RobotAction>(_inFlight.Count + _buffer.Count);
        pending.AddRange(_inFlight.Select(f => f.Action));
        pending.AddRange(_buffer.Select(p => p.Action));
        _inFlight.Clear();
        _buffer.Clear();
        if (pending.Count == 0)
        {
            Detach(new RobotStoppedException("The robot was stopped by the user (Robot.Stop); connect again to go on.", StoppedCode));
            Log(LogLevel.INFO, $"\"{_host.Name}\" stopped by the user; nothing was waiting. The link is closed.");
            _ = CloseQuietlyAsync(link.Driver);
            return;
        }
        RobotAction stopped = pending[0];
        pending.RemoveAt(0);
        Abandon(stopped, pending, StoppedByUser, StoppedCode, issue);
        _ = CloseQuietlyAsync(link.Driver);
    }
}
