namespace Machina;

public sealed partial class Robot
{
    /// <summary>The cursor the getters read: the state after the last issued action (offline) or executed action (online).</summary>
    private RobotCursor StateCursor => _session?.ExecutionCursor ?? _issueCursor;

    /// <summary>A snapshot of the whole state after the last issued action (offline) or the last executed action (online).</summary>
    public RobotState GetCurrentState() => _session is null ? GetIssuedState() : GetExecutedState();

    /// <summary>Tool tip position in mm after the last issued action, or null when unknown (before the first absolute move, or after a joint move).</summary>
    public Point? GetCurrentPosition() => StateCursor.Position is Vector v ? v : null;

    /// <summary>Tool orientation after the last issued action, or null when unknown.</summary>
    public Rotation? GetCurrentRotation() => StateCursor.Rotation;

    /// <summary>Joint angles in degrees after the last issued action, or null when unknown.</summary>
    public Joints? GetCurrentAxes() => StateCursor.Axes;

    /// <summary>External axes used with Cartesian targets, or null when never set.</summary>
    public ExternalAxes? GetCurrentExternalAxes() => StateCursor.ExternalAxesCartesian;

    /// <summary>Current speed, mm/s.</summary>
    public double GetCurrentSpeed() => StateCursor.Speed;

    /// <summary>Current acceleration, mm/s².</summary>
    public double GetCurrentAcceleration() => StateCursor.Acceleration;

    /// <summary>Current blend radius, mm.</summary>
    public double GetCurrentPrecision() => StateCursor.Precision;

    /// <summary>Current motion type.</summary>
    public MotionType GetCurrentMotionMode() => StateCursor.MotionType;

    /// <summary>Current frame of relative actions.</summary>
    public ReferenceCS GetCurrentReferenceCS() => StateCursor.ReferenceCS;

    /// <summary>The attached tool, or null.</summary>
    public Tool? GetCurrentTool() => StateCursor.Tool;
}
