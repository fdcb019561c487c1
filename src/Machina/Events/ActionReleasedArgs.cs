using System.Text;

namespace Machina;

/// <summary>Payload of <c>Robot.ActionReleased</c>: an action was sent to the controller.</summary>
public sealed class ActionReleasedArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public ActionReleasedArgs(RobotAction lastAction, int pendingRelease, RobotState state) : base(state)
    {
        LastAction = lastAction ?? throw new ArgumentNullException(nameof(lastAction));
        PendingRelease = pendingRelease;
    }

    /// <summary>The action that was sent.</summary>
    public RobotAction LastAction { get; }

    /// <summary>How many issued actions are still waiting to be sent.</summary>
    public int PendingRelease { get; }

    /// <summary>Same as <see cref="PendingRelease"/> (the original's name).</summary>
    public int PendingReleaseToDevice => PendingRelease;

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(220);
        AppendHead(sb, "action-released", LastAction);
        sb.Append(",\"pend\":").Append(Num.I(PendingRelease)).Append(',');
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
