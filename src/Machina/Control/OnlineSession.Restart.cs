namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>The reason every action whose outcome a controller restart left unknown fails with.</summary>
    internal const string RestartedReason = "the controller restarted; this action may or may not have run";

    /// <summary>The code of <see cref="RestartedReason"/> in <see cref="ActionFailedException.ControllerCode"/>.</summary>
    internal const string RestartedCode = "restarted";

    /// <summary>
    /// Actions a controller restart left with an unknown outcome and that were not sent again, until a wait reports them (the
    /// next wait for completion or for room that would succeed throws once, naming them).
    /// </summary>
    private readonly List<RobotAction> _notResent = [];

    /// <summary>Send again the actions a controller restart left with an unknown outcome (<c>Robot.ResendAfterControllerRestart</c>).</summary>
    internal bool ResendAfterControllerRestart { get; set; }

    /// <summary>
    /// The controller does not know the actions sent on an earlier connection and not confirmed (it restarted: its progress
    /// was reset, or it is another controller): whether each ran is unknown. By default those the controller would have
    /// acknowledged end failed with <see cref="RestartedReason"/>, are reported at WARNING with their ids and are never sent
    /// again; with <see cref="ResendAfterControllerRestart"/> they are sent again. Actions that send nothing to acknowledge,
    /// and those never sent, go back to the buffer and are sent as usual. Called on the loop, under the issue lock, before
    /// the cursors are set from the handshake; returns the actions that failed (their events are raised once the link is up).
    /// </summary>
    private List<RobotAction> SettleAfterRestart(DeviceProgress progress)
    {
        string what = progress.IsFresh
            ? "The controller restarted (its progress is 0 executed, 0 received)"
            : $"The controller restarted or is another controller (its progress, last executed {progress.LastExecutedId}, last received "
                + $"{progress.LastReceivedId}, names none of them)";
        var unknown = _inFlight.Where(f => f.Acked).Select(f => f.Action).ToList();
        if (unknown.Count == 0 || ResendAfterControllerRestart)
        {
            if (unknown.Count > 0)
            {
                Log(LogLevel.WARNING, $"{what}: the {unknown.Count} actions sent before the restart and not confirmed {IdList(unknown)} "
                    + "are sent again (ResendAfterControllerRestart), with targets recomputed from where the robot is; any it already ran runs twice.");
            }
            RequeueInFlight();
            return [];
        }
        var kept = _inFlight.Where(f => !f.Acked).Select(f => new Pending(f.Action, f.Frame)).ToList();
        _inFlight.Clear();
        PutBackInFront(kept);
        _notResent.AddRange(unknown);
        Log(LogLevel.WARNING, $"{what}: the {unknown.Count} actions sent before the restart and not confirmed {IdList(unknown)} may or may "
            + "not have run and are not sent again; each ends failed (ActionFailed). Check the robot, then issue again what must run, or set "
            + $"ResendAfterControllerRestart for a program that may run an action twice. The {_buffer.Count} actions never sent are sent now.");
        return unknown;
    }

    /// <summary>Raises <c>ActionFailed</c> for each action a restart left with an unknown outcome (on the loop, once the link is up).</summary>
    private void ReportNotResent(List<RobotAction> unknown)
    {
        if (unknown.Count == 0 || !_host.IsListening(OnlineEvent.Failed))
        {
            return;
        }
        foreach (RobotAction action in unknown)
        {
            _events.Post(new ActionFailedArgs(NotResent(action, 1), [], _execution.Snapshot()));
        }
    }

    /// <summary>
    /// The failure a wait reports once after a restart left actions with an unknown outcome (null when there is none): it
    /// names the first of them and counts them all; the list is then emptied.
    /// </summary>
    private ActionFailedException? TakeNotResent()
    {
        if (_notResent.Count == 0)
        {
            return null;
        }
        ActionFailedException failure = NotResent(_notResent[0], _notResent.Count, IdList(_notResent));
        _notResent.Clear();
        return failure;
    }

    private static ActionFailedException NotResent(RobotAction action, int count, string? ids = null) => new(action, RestartedReason, RestartedCode,
        count == 1
            ? $"{action.ToInstruction()} (id {action.Id}) was not sent again: {RestartedReason}. Check the robot, then issue it again if it must run."
            : $"{count} actions {ids} were not sent again: {RestartedReason} (the first: {action.ToInstruction()}, id {action.Id}). "
                + "Check the robot, then issue again what must run.");

    /// <summary>Ids as ranges, "(ids 12-18, 20)", or "(id 12)" for one.</summary>
    internal static string IdList(IReadOnlyList<RobotAction> actions)
    {
        var text = new System.Text.StringBuilder(actions.Count == 1 ? "(id " : "(ids ");
        for (int i = 0; i < actions.Count;)
        {
            int start = actions[i].Id, end = start;
            while (++i < actions.Count && actions[i].Id == end + 1)
            {
                end++;
            }
            text.Append(text[^1] == ' ' ? "" : ", ").Append(start.ToString(Num.Inv));
            if (end != start)
            {
                text.Append('-').Append(end.ToString(Num.Inv));
            }
        }
        return text.Append(')').ToString();
    }
}
