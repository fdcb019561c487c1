using System.Text;

namespace Machina;

/// <summary>Payload of <c>Robot.ActionIssued</c>: the action that was just accepted and the state it leads to.</summary>
public sealed class ActionIssuedArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public ActionIssuedArgs(RobotAction lastAction, RobotState state) : base(state) =>
        LastAction = lastAction ?? throw new ArgumentNullException(nameof(lastAction));

    /// <summary>The action that was issued.</summary>
    public RobotAction LastAction { get; }

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(200);
        AppendHead(sb, "action-issued", LastAction);
        sb.Append(',');
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
