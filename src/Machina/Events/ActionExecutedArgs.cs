using System.Text;

namespace Machina;

/// <summary>Payload of <c>Robot.ActionExecuted</c>: the controller reported an action as done.</summary>
public sealed class ActionExecutedArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public ActionExecutedArgs(RobotAction lastAction, int pendingExecutionOnDevice, int pendingExecutionTotal, RobotState state) : base(state)
    {
        LastAction = lastAction ?? throw new ArgumentNullException(nameof(lastAction));
        PendingExecutionOnDevice = pendingExecutionOnDevice;
        PendingExecutionTotal = pendingExecutionTotal;
    }

    /// <summary>The action that was executed.</summary>
    public RobotAction LastAction { get; }

    /// <summary>Actions sent to the controller and not executed yet, when this one was reported done.</summary>
    public int PendingExecutionOnDevice { get; }

    /// <summary>
    /// Actions issued so far and not executed yet (sent or still waiting), when this one was reported done: it grows again
    /// when more actions are issued after it, so it reaches 0 at the end of a program only once the program was all issued.
    /// </summary>
    public int PendingExecutionTotal { get; }

    /// <summary>For a read (<see cref="ActionReadInput"/>), the value the controller read (a digital input: 1 or 0); else null.</summary>
    public double? ReadValue { get; init; }

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(240);
        AppendHead(sb, "action-executed", LastAction);
        sb.Append(",\"pendDev\":").Append(Num.I(PendingExecutionOnDevice))
          .Append(",\"pendTot\":").Append(Num.I(PendingExecutionTotal)).Append(',');
        if (ReadValue is double value)
        {
            sb.Append("\"value\":").Append(Num.R(value)).Append(',');
        }
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
