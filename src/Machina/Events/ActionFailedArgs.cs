using System.Text;

namespace Machina;

/// <summary>
/// Payload of <c>Robot.ActionFailed</c>: the controller reported that it could not run an action and stopped. The state is
/// where the robot really is; actions issued after the failed one were cancelled (never executed) and are listed.
/// </summary>
public sealed class ActionFailedArgs : MachinaEventArgs
{
    /// <summary>Creates the payload, with no cancelled actions.</summary>
    public ActionFailedArgs(ActionFailedException failure, RobotState state) : this(failure, [], state)
    {
    }

    /// <summary>Creates the payload; <paramref name="cancelledActions"/> are the actions after the failed one that will never run.</summary>
    public ActionFailedArgs(ActionFailedException failure, IReadOnlyList<RobotAction> cancelledActions, RobotState state) : base(state)
    {
        Failure = failure ?? throw new ArgumentNullException(nameof(failure));
        CancelledActions = cancelledActions ?? throw new ArgumentNullException(nameof(cancelledActions));
    }

    /// <summary>The failure: the action, the controller's reason and code.</summary>
    public ActionFailedException Failure { get; }

    /// <summary>The action the controller could not run.</summary>
    public RobotAction Action => Failure.Action;

    /// <summary>What the controller said, in its own words.</summary>
    public string Reason => Failure.ControllerReason;

    /// <summary>
    /// Actions issued after the failed one, oldest first: they were cancelled (sent ones were dropped by the stopped
    /// controller, waiting ones were never sent) and will never run or be reported executed. Issue them again if you want them.
    /// </summary>
    public IReadOnlyList<RobotAction> CancelledActions { get; }

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(280);
        AppendHead(sb, "action-failed", Action);
        sb.Append(",\"error\":");
        AppendJsonString(sb, Reason);
        sb.Append(",\"code\":");
        if (Failure.ControllerCode is null)
        {
            sb.Append("null");
        }
        else
        {
            AppendJsonString(sb, Failure.ControllerCode);
        }
        sb.Append(",\"cancelled\":[");
        for (int i = 0; i < CancelledActions.Count; i++)
        {
            if (i > 0)
            {
                sb.Append(',');
            }
            sb.Append(Num.I(CancelledActions[i].Id));
        }
        sb.Append("],");
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
