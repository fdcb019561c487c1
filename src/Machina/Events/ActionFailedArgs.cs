using System.Text;

namespace Machina;

/// <summary>
/// Payload of <c>Robot.ActionFailed</c>: the controller reported that it could not run an action and stopped. The state is
/// where the robot really is; actions issued after the failed one were not executed.
/// </summary>
public sealed class ActionFailedArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public ActionFailedArgs(ActionFailedException failure, RobotState state) : base(state)
    {
        Failure = failure ?? throw new ArgumentNullException(nameof(failure));
    }

    /// <summary>The failure: the action, the controller's reason and code.</summary>
    public ActionFailedException Failure { get; }

    /// <summary>The action the controller could not run.</summary>
    public RobotAction Action => Failure.Action;

    /// <summary>What the controller said, in its own words.</summary>
    public string Reason => Failure.ControllerReason;

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
        sb.Append(',');
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
