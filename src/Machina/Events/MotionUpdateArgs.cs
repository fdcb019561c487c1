using System.Text;

namespace Machina;

/// <summary>Payload of <c>Robot.MotionUpdate</c>: where the robot is right now, as reported by the controller while it moves.</summary>
public sealed class MotionUpdateArgs : MachinaEventArgs
{
    /// <summary>Creates the payload.</summary>
    public MotionUpdateArgs(RobotState state) : base(state) { }

    /// <inheritdoc/>
    public override string ToJsonString()
    {
        var sb = new StringBuilder(200);
        sb.Append("{\"event\":\"motion-update\",");
        AppendPose(sb);
        return sb.Append('}').ToString();
    }
}
