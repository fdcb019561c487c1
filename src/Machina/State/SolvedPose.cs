namespace Machina;

/// <summary>
/// Everything a cursor's kinematics reads for one motion: the model, the joints before it, the TCP target (a Cartesian motion) or
/// the target joints (a joint move, <paramref name="targetAxes"/>), the tool's tip, an arc's through point, the motion type and the
/// speed. Two keys are equal only when every number has the same bits (0 and −0 differ, so do two NaNs of different payloads): equal
/// keys give the same joints, pose and issues.
/// </summary>
internal readonly struct PoseSolveKey(
    RobotModel model, Joints? prevAxes, Vector position, Rotation rotation, Tool? tool, Vector? through, Rotation? throughRotation,
    MotionType motionType, double speed, Joints? targetAxes = null) : IEquatable<PoseSolveKey>
{
    private readonly Joints? _targetAxes = targetAxes;
    private readonly RobotModel _model = model;
    private readonly Joints? _prevAxes = prevAxes;
    private readonly Vector _position = position;
    private readonly Rotation _rotation = rotation;
    private readonly bool _hasTool = tool is not null;
    private readonly Vector _tip = tool?.TcpPosition ?? default;
    private readonly Rotation _tipRotation = tool?.TcpOrientation ?? default;
    private readonly Vector? _through = through;
    private readonly Rotation? _throughRotation = throughRotation;
    private readonly MotionType _motionType = motionType;
    private readonly double _speed = speed;

    /// <summary>True when both keys describe the same solve, number for number (bitwise).</summary>
    public bool Equals(PoseSolveKey other) =>
        ReferenceEquals(_model, other._model) && _motionType == other._motionType && Same(_speed, other._speed)
        && Same(_prevAxes, other._prevAxes) && Same(_position, other._position) && Same(_rotation, other._rotation)
        && _hasTool == other._hasTool && Same(_tip, other._tip) && Same(_tipRotation, other._tipRotation)
        && Same(_through, other._through) && Same(_throughRotation, other._throughRotation) && Same(_targetAxes, other._targetAxes);

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is PoseSolveKey other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(_model, _position, _speed);

    /// <summary>Equal keys.</summary>
    public static bool operator ==(PoseSolveKey a, PoseSolveKey b) => a.Equals(b);

    /// <summary>Different keys.</summary>
    public static bool operator !=(PoseSolveKey a, PoseSolveKey b) => !a.Equals(b);

    private static bool Same(double a, double b) => BitConverter.DoubleToInt64Bits(a) == BitConverter.DoubleToInt64Bits(b);

    private static bool Same(Vector a, Vector b) => Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z);

    private static bool Same(Rotation a, Rotation b) => Same(a.W, b.W) && Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z);

    private static bool Same(Joints a, Joints b) =>
        Same(a.J1, b.J1) && Same(a.J2, b.J2) && Same(a.J3, b.J3) && Same(a.J4, b.J4) && Same(a.J5, b.J5) && Same(a.J6, b.J6);

    private static bool Same(Vector? a, Vector? b) => a is Vector x ? b is Vector y && Same(x, y) : b is null;

    private static bool Same(Rotation? a, Rotation? b) => a is Rotation x ? b is Rotation y && Same(x, y) : b is null;

    private static bool Same(Joints? a, Joints? b) => a is Joints x ? b is Joints y && Same(x, y) : b is null;
}

/// <summary>
/// A motion's solution for the state in <see cref="Key"/>: a Cartesian motion's joints (null: unreachable), or a joint move's TCP pose
/// (<see cref="Tcp"/>, its forward kinematics with the tool), and the kinematic issues.
/// </summary>
internal sealed record SolvedPose(PoseSolveKey Key, Joints? Axes, IReadOnlyList<KinematicIssue> Issues)
{
    /// <summary>A joint move's TCP pose; default for a Cartesian motion.</summary>
    internal Pose Tcp { get; init; }
}
