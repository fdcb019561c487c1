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
    internal async Task StopAsync(CancellationToken cancellationToken)
    {
        Connection link = await AskAsync(() =>
        {
            Connection current = RequireLink("stop");
            _stoppedByUser = current;
            return current;
        }).ConfigureAwait(false);
        try
        {
            await link.Driver.StopMotionAsync(cancellationToken).ConfigureAwait(false);
        }
        catch
        {
            await AskAsync(() => _stoppedByUser = null).ConfigureAwait(false);
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
