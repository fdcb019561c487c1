namespace Machina;

/// <summary>How the robot travels to the next target.</summary>
public enum MotionType
{
    /// <summary>The tool tip follows a straight line (default).</summary>
    Linear,
    /// <summary>Each joint turns at its own pace; the tool tip path is a curve but the motion is easier for the arm.</summary>
    Joint,
}
