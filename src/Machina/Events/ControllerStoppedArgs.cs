using System.Text;

namespace Machina;

/// <summary>
/// Payload of <c>Robot.ControllerStopped</c> and <c>Robot.ControllerResumed</c>: the controller stopped on its own (protective
/// or emergency stop) or runs again. The actions not executed yet are kept, and listed here.
/// </summary>
public sealed class ControllerStoppedArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public ControllerStoppedArgs(bool isStopped, MachinaException? reason, IReadOnlyList<RobotAction> pendingActions, RobotState state) : base(state)
    {
        IsStopped = isStopped;
        Reason = reason;
        PendingActions = pendingActions ?? throw new ArgumentNullException(nameof(pendingActions));
    }

    /// <summary>True when the controller stopped, false when it runs again.</summary>
    public bool IsStopped { get; }

    /// <summary>Why it stopped (null when it runs again).</summary>
    public MachinaException? Reason { get; }

    /// <summary>Issued actions not executed yet, oldest first; they run once the controller runs again.</summary>
    public IReadOnlyList<RobotAction> PendingActions { get; }

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(240);
        sb.Append(IsStopped ? "{\"event\":\"controller-stopped\",\"error\":" : "{\"event\":\"controller-resumed\",\"error\":");
        if (Reason is null)
        {
            sb.Append("null");
        }
        else
        {
            AppendJsonString(sb, Reason.Message);
        }
        sb.Append(",\"pending\":").Append(Num.I(PendingActions.Count)).Append(',');
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
