namespace Machina;

internal sealed partial class RobotCursor
{
    /// <summary>
    /// Starts over from what a controller reported when it connected: every setting back to Machina's defaults, and the
    /// pose, joints and external axes it gave (those it did not give stay unknown). The model and strictness are kept.
    /// </summary>
    internal void ResetToReported(Vector? position, Rotation? rotation, Joints? axes, ExternalAxes? externalAxes)
    {
        Reset();
        if (position is Vector p)
        {
            Position = PrevPosition = p;
        }
        if (rotation is Rotation r)
        {
            Rotation = PrevRotation = r;
        }
        if (axes is Joints j)
        {
            Axes = PrevAxes = j;
        }
        ExternalAxesCartesian = ExternalAxesJoints = externalAxes;
    }

    /// <summary>Records where a controller reports the robot is while it moves (the motion cursor; settings are not reported).</summary>
    internal void SetLivePose(Vector position, Rotation rotation, Joints axes, ExternalAxes? externalAxes)
    {
        Position = position;
        Rotation = rotation;
        Axes = axes;
        ExternalAxesCartesian = externalAxes;
    }

    /// <summary>
    /// Puts the pose where a controller last reported the robot, keeping every setting (speed, tool, frame…): used when the
    /// controller stopped before reaching the target the cursor holds. External axes change only when reported.
    /// </summary>
    internal void StopAtReported(Vector position, Rotation rotation, Joints axes, ExternalAxes? externalAxes)
    {
        Position = PrevPosition = position;
        Rotation = PrevRotation = rotation;
        Axes = PrevAxes = axes;
        if (externalAxes is not null)
        {
            ExternalAxesCartesian = externalAxes;
        }
    }
}
