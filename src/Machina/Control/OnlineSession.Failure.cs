namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>The controller's last reported failure, until the next connection: a wait with nothing pending reports it.</summary>
    private ActionFailedException? _failure;

    /// <summary>
    /// True once the current link reported a live pose since the last acknowledgement (the motion cursor then says where the
    /// robot really is; an older one predates the target the acknowledgement confirmed).
    /// </summary>
    private bool _liveOnLink;

    /// <summary>A failure reported by a driver (wire id): applied under the issue lock, then the link is closed.</summary>
    private void OnFailed(Connection link, int wireId, string reason, string? code)
    {
        if (!ReferenceEquals(_link, link))
        {
            return;
        }
        if (ReferenceEquals(_stoppedByUser, link))
        {
            // The controller reports the program the user stopped as a failure of the action it ran: say who stopped it.
            (reason, code) = (StoppedByUser, StoppedCode);
        }
        MachinaException? unknown = null;
        WithIssueCursor(issue => unknown = Fail(wireId, reason, code, issue));
        if (unknown is not null)
        {
            Fault(link, unknown);
        }
        else
        {
            _ = CloseQuietlyAsync(link.Driver);
        }
        StopApplied(link);
    }

    /// <summary>
    /// A failure reported by how far the controller's program got (<see cref="IDeviceListener.OnFailedAfter"/>): the first action in
    /// flight after wire id <paramref name="executedId"/> that the controller acknowledges failed. Nothing such in flight: nothing failed
    /// that the session sent, and nothing is reported.
    /// </summary>
    private void OnFailedAfter(Connection link, int executedId, string reason, string? code)
    {
        if (!ReferenceEquals(_link, link))
        {
            return;
        }
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked && f.WireId > executedId)
            {
                Log(LogLevel.ERROR, $"The controller could not run action {f.WireId.ToString(Num.Inv)}: {reason}");
                OnFailed(link, f.WireId, reason, code);
                return;
            }
        }
    }

    /// <summary>
    /// Applies a failure (on the loop, under the issue lock): what was released before the failed action ran, the failed action raises
    /// <c>ActionFailed</c>, everything after it is cancelled, the cursors go back to where the robot is, waiters fail and the
    /// link is forgotten (the controller's program stopped). Returns a link fault instead when no action waits with that id.
    /// </summary>
    private MachinaException? Fail(int wireId, string reason, string? code, RobotCursor issue)
    {
        int found = -1, index = 0;
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked && f.WireId == wireId)
            {
                found = index;
                break;
            }
            index++;
        }
        if (found < 0)
        {
            return new RobotConnectionException(
                $"The controller reported that it could not run action {wireId}, which is not waiting for execution: {reason}", code);
        }
        var ran = new List<InFlight>(found);
        for (int i = 0; i < found; i++)
        {
            ran.Add(_inFlight.Dequeue());
        }
        RobotAction failedAction = _inFlight.Dequeue().Action;
        var cancelled = new List<RobotAction>(_inFlight.Count + _buffer.Count);
        cancelled.AddRange(_inFlight.Select(f => f.Action));
        cancelled.AddRange(_buffer.Select(p => p.Action));
        _inFlight.Clear();
        _buffer.Clear();
        for (int i = 0; i < ran.Count; i++)
        {
            int after = ran.Count - 1 - i;
            Execute(ran[i], after, after);
        }
        Abandon(failedAction, cancelled, reason, code, issue);
        return null;
    }

    /// <summary>
    /// The end of a failure (on the loop, under the issue lock; nothing waits any more): the cursors go back to where the robot
    /// is, <paramref name="failedAction"/> raises <c>ActionFailed</c> with the <paramref name="cancelled"/> actions after it,
    /// waiters fail and the link is forgotten.
    /// </summary>
    private void Abandon(RobotAction failedAction, List<RobotAction> cancelled, string reason, string? code, RobotCursor issue)
    {
        if (_liveOnLink && _motion is { Position: Vector at, Rotation: Rotation facing, Axes: Joints axes } live)
        {
            _execution.StopAtReported(at, facing, axes, live.ExternalAxesCartesian);
        }
        _release.CopyFrom(_execution);
        issue.CopyFrom(_execution);

        var failure = new ActionFailedException(failedAction, reason, code);
        _failure = failure;
        Detach(failure);
        Log(LogLevel.ERROR, $"\"{_host.Name}\" stopped: {failure.Message} {Counted.Of(cancelled.Count, "action")} after it {(cancelled.Count == 1 ? "was" : "were")} cancelled; the link is closed. "
            + "Connect again to go on from where the robot is.");
        if (_host.IsListening(OnlineEvent.Failed))
        {
            _events.Post(new ActionFailedArgs(failure, cancelled, _execution.Snapshot()));
        }
        if (_host.IsListening(OnlineEvent.StopChanged))
        {
            _events.Post(new ControllerStoppedArgs(true, failure, [], _execution.Snapshot()));
        }
    }
}
