namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>Not found among the actions an earlier connection sent.</summary>
    private const int Unknown = -2;

    /// <summary>Id of the last action the controller acknowledged, on any connection (0 before the first).</summary>
    private int _lastAcknowledgedId;

    /// <summary>
    /// Sets the cursors and the queues for a new connection (on the loop, under the issue lock). Returns why the connection is refused, or null.
    /// <list type="bullet">
    /// <item>Actions sent on an earlier connection and not confirmed, with a controller that reports its progress and knows
    /// them: those it executed count as executed, those it still holds wait for their acknowledgement, the rest are sent
    /// again with unchanged targets. Nothing runs twice.</item>
    /// <item>A controller still busy with requests this robot did not send (another program, or a restarted host): refused.</item>
    /// <item>A controller that reports its progress but does not know them (it restarted, or it is another controller): whether
    /// they ran is unknown; by default they end failed and are not sent again (<see cref="SettleAfterRestart"/>).</item>
    /// <item>Otherwise (first connection, or a driver that does not report progress): the controller's pose becomes every
    /// cursor's state and everything not confirmed is sent (again).</item>
    /// </list>
    /// </summary>
    private string? Resume(DeviceHandshake handshake, IDeviceDriver driver, RobotCursor issue)
    {
        DeviceProgress? progress = handshake.Progress;
        int executed = Unknown, held = Unknown;
        if (progress is DeviceProgress p && !p.IsFresh)
        {
            executed = Locate(p.LastExecutedId, driver);
            held = Locate(p.LastReceivedId, driver);
        }
        bool known = executed != Unknown && held >= executed;
        if (progress is { IsBusy: true } busy && !known)
        {
            return $"The controller is still executing requests this robot did not send (last executed {busy.LastExecutedId}, last received "
                + $"{busy.LastReceivedId}). Wait until it is idle, or restart the driver program, then connect again.";
        }
        if (known && _inFlight.Count > 0)
        {
            ResumeWhereTheControllerIs(executed + 1, held - executed, driver, handshake);
            return null;
        }
        List<RobotAction> notResent = [];
        if (_inFlight.Count > 0 && progress is DeviceProgress reported && (!reported.IsFresh || _lastAcknowledgedId != 0))
        {
            notResent = SettleAfterRestart(reported);
        }
        else if (_inFlight.Count > 0)
        {
            // No progress report, or a controller that says it ran nothing while this robot never saw an acknowledgement: nothing
            // tells a restart from requests that never arrived (docs/reliability.md, "Controller restarts").
            Log(LogLevel.WARNING, progress is null
                ? $"The driver does not report which requests it executed (driver {handshake.Version}; 1.6 does): the {Counted.Of(_inFlight.Count, "action")} sent "
                    + "before the connection was lost are sent again, and any the robot already ran will run twice."
                : $"The controller reports that it ran nothing, and none of the {Counted.Of(_inFlight.Count, "action")} sent before the connection was lost was "
                    + "acknowledged: they are sent again, with targets recomputed from where the robot is (had the controller run some and restarted, "
                    + "those would run twice).");
            RequeueInFlight();
        }
        InitialiseCursors(handshake, issue);
        ReportNotResent(notResent);
        return null;
    }

    /// <summary>
    /// Where a controller id falls among the actions in flight: its index, -1 for the last action acknowledged before them
    /// (or 0 when nothing was acknowledged yet), or <see cref="Unknown"/>.
    /// </summary>
    private int Locate(int controllerId, IDeviceDriver driver)
    {
        int index = 0, found = Unknown;
        foreach (InFlight f in _inFlight)
        {
            if (f.Acked && f.WireId == controllerId)
            {
                found = index;
            }
            index++;
        }
        if (found != Unknown)
        {
            return found;
        }
        int before = _lastAcknowledgedId == 0 ? 0 : driver.WireId(_lastAcknowledgedId);
        return controllerId == before ? -1 : Unknown;
    }

    /// <summary>The first <paramref name="executedCount"/> actions in flight ran, the next <paramref name="heldCount"/> are on the controller, the rest go back to the buffer.</summary>
    private void ResumeWhereTheControllerIs(int executedCount, int heldCount, IDeviceDriver driver, DeviceHandshake handshake)
    {
        for (int i = 0; i < executedCount; i++)
        {
            Execute(_inFlight.Dequeue());
        }
        var remaining = _inFlight.ToList();
        _inFlight.Clear();
        _release.CopyFrom(_execution);
        foreach (InFlight f in remaining.Take(heldCount))
        {
            _release.TryApply(f.Action);
            if (f.Acked)
            {
                driver.Adopt(f.Action.Id);
            }
            _inFlight.Enqueue(f);
        }
        var resend = remaining.Skip(heldCount).Select(f => new Pending(f.Action, f.Frame)).ToList();   // unchanged targets, same frames
        int resent = resend.Count;   // counted first: PutBackInFront appends the buffer to the list
        PutBackInFront(resend);
        Log(LogLevel.INFO, $"Resumed where the controller is: {Counted.Of(executedCount, "action")} ran while disconnected, {heldCount} {(heldCount == 1 ? "is" : "are")} still on the controller, "
            + $"{resent} {(resent == 1 ? "is" : "are")} sent again.");
        if (heldCount == 0 && handshake.Position is Vector at && _execution.Position is Vector expected && Vector.Distance(at, expected) > 1)
        {
            Log(LogLevel.WARNING, $"The robot is at {at}, {Num.F(Vector.Distance(at, expected), 1)} mm from where its last action left it: "
                + "it was moved while disconnected. The remaining actions keep their targets.");
        }
    }

    /// <summary>Moves every action in flight back to the front of the buffer, to be released again.</summary>
    private void RequeueInFlight()
    {
        var actions = _inFlight.Select(f => new Pending(f.Action, f.Frame)).ToList();
        _inFlight.Clear();
        PutBackInFront(actions);
    }

    private void PutBackInFront(List<Pending> actions)
    {
        if (actions.Count == 0)
        {
            return;
        }
        actions.AddRange(_buffer);
        _buffer.Clear();
        foreach (Pending p in actions)
        {
            _buffer.Enqueue(p);
        }
    }
}
