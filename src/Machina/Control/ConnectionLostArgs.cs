using System.Text;

namespace Machina;

/// <summary>
/// Payload of <c>Robot.ConnectionLost</c>: the link to the controller failed (socket closed, garbage received, no answer,
/// unknown acknowledgement). The actions that were not confirmed as executed are kept and listed here.
/// </summary>
public sealed class ConnectionLostArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public ConnectionLostArgs(MachinaException error, IReadOnlyList<RobotAction> pendingActions, RobotState state) : base(state)
    {
        Error = error ?? throw new ArgumentNullException(nameof(error));
        PendingActions = pendingActions ?? throw new ArgumentNullException(nameof(pendingActions));
    }

    /// <summary>What went wrong.</summary>
    public MachinaException Error { get; }

    /// <summary>Issued actions not confirmed as executed, oldest first; they are sent again after the next connection.</summary>
    public IReadOnlyList<RobotAction> PendingActions { get; }

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(240);
        sb.Append("{\"event\":\"connection-lost\",\"error\":");
        AppendJsonString(sb, Error.Message);
        sb.Append(",\"pending\":").Append(Num.I(PendingActions.Count)).Append(',');
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
