namespace Machina;

public sealed partial class Robot
{
    /// <summary>Reads the state the getters report, under its lock: the last issued action (offline) or executed action (online).</summary>
    private T ReadState<T>(Func<RobotCursor, T> read)
    {
        if (_session is { } session)
        {
            return session.ReadExecution(read);
        }
        lock (_issueLock)
        {
            return read(_issueCursor);
        }
    }

    /// <summary>A snapshot of the whole state after the last issued action (offline) or the last executed action (online).</summary>
    public RobotState GetCurrentState() => _session is null ? GetIssuedState() : GetExecutedState();

    /// <summary>Tool tip position in mm after the last issued action, or null when unknown (before the first absolute move, or after a joint move).</summary>
    public Point? GetCurrentPosition() => ReadState(static c => c.Position is Vector v ? (Point?)v : null);

    /// <summary>Tool orientation after the last issued action, or null when unknown.</summary>
    public Rotation? GetCurrentRotation() => ReadState(static c => c.Rotation);

    /// <summary>Joint angles in degrees after the last issued action, or null when unknown.</summary>
    public Joints? GetCurrentAxes() => ReadState(static c => c.Axes);

    /// <summary>External axes used with Cartesian targets, or null when never set.</summary>
    public ExternalAxes? GetCurrentExternalAxes() => ReadState(static c => c.ExternalAxesCartesian);

    /// <summary>Current speed, mm/s.</summary>
    public double GetCurrentSpeed() => ReadState(static c => c.Speed);

    /// <summary>Current acceleration, mm/s².</summary>
    public double GetCurrentAcceleration() => ReadState(static c => c.Acceleration);

    /// <summary>Current blend radius, mm.</summary>
    public double GetCurrentPrecision() => ReadState(static c => c.Precision);

    /// <summary>Current motion type.</summary>
    public MotionType GetCurrentMotionMode() => ReadState(static c => c.MotionType);

    /// <summary>Current frame of relative actions.</summary>
    public ReferenceCS GetCurrentReferenceCS() => ReadState(static c => c.ReferenceCS);

    /// <summary>The attached tool, or null.</summary>
    public Tool? GetCurrentTool() => ReadState(static c => c.Tool);
}
