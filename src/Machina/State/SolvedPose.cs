using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// Everything a cursor's kinematics reads for one motion: the model, the joints before it, the TCP target (a Cartesian motion) or
/// the target joints (a joint move), the tool's tip, an arc's through point, the motion type and the
/// speed. Two keys are equal only when every number has the same bits (0 and −0 differ, so do two NaNs of different payloads): equal
/// keys give the same joints, pose and issues. Each waiting action of a stream keeps one, so it holds only what a line needs
/// (144 bytes, 330 before): the tool by reference (a tool is immutable; its tip is compared), the rest of an arc or a joint move in a
/// small object of its own.
/// </summary>
internal readonly struct PoseSolveKey : IEquatable<PoseSolveKey>
{
    private readonly RobotModel _model;
    private readonly Tool? _tool;
    private readonly Extra? _extra;
    private readonly Vector _position;
    private readonly Rotation _rotation;
    private readonly Joints _prevAxes;
    private readonly double _speed;
    private readonly MotionType _motionType;
    private readonly bool _hasPrevAxes;

    /// <summary>An arc's through point and orientation, or a joint move's target joints: what a line's key has no room for.</summary>
    private sealed class Extra(Vector? through, Rotation? throughRotation, Joints? targetAxes)
    {
        internal bool SameAs(Extra other) =>
            Same(through, other.Through) && Same(throughRotation, other.ThroughRotation) && Same(targetAxes, other.TargetAxes);

        private Vector? Through => through;

        private Rotation? ThroughRotation => throughRotation;

        private Joints? TargetAxes => targetAxes;
    }

    /// <summary>The key of one solve; <paramref name="tool"/>'s tip and orientation are what count of it, not its name.</summary>
    internal PoseSolveKey(
        RobotModel model, Joints? prevAxes, Vector position, Rotation rotation, Tool? tool, Vector? through, Rotation? throughRotation,
        MotionType motionType, double speed, Joints? targetAxes = null)
    {
        _model = model;
        _hasPrevAxes = prevAxes.HasValue;
        _prevAxes = prevAxes.GetValueOrDefault();
        _position = position;
        _rotation = rotation;
        _tool = tool;
        _extra = through is null && throughRotation is null && targetAxes is null ? null : new Extra(through, throughRotation, targetAxes);
        _motionType = motionType;
        _speed = speed;
    }

    /// <summary>True when both keys describe the same solve, number for number (bitwise).</summary>
    public bool Equals(PoseSolveKey other) =>
        ReferenceEquals(_model, other._model) && _motionType == other._motionType && SameBits.Of(_speed, other._speed)
        && _hasPrevAxes == other._hasPrevAxes && SameBits.Of(_prevAxes, other._prevAxes) && SameBits.Of(_position, other._position)
        && SameBits.Of(_rotation, other._rotation) && SameTip(_tool, other._tool) && SameExtra(_extra, other._extra);

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is PoseSolveKey other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(_model, _position, _speed);

    /// <summary>Equal keys.</summary>
    public static bool operator ==(PoseSolveKey a, PoseSolveKey b) => a.Equals(b);

    /// <summary>Different keys.</summary>
    public static bool operator !=(PoseSolveKey a, PoseSolveKey b) => !a.Equals(b);

    private static bool SameTip(Tool? a, Tool? b) =>
        ReferenceEquals(a, b) || (a is not null && b is not null && SameBits.Of(a.TcpPosition, b.TcpPosition) && SameBits.Of(a.TcpOrientation, b.TcpOrientation));

    private static bool SameExtra(Extra? a, Extra? b) => ReferenceEquals(a, b) || (a is not null && b is not null && a.SameAs(b));

    private static bool Same(Vector? a, Vector? b) => a is Vector x ? b is Vector y && SameBits.Of(x, y) : b is null;

    private static bool Same(Rotation? a, Rotation? b) => a is Rotation x ? b is Rotation y && SameBits.Of(x, y) : b is null;

    private static bool Same(Joints? a, Joints? b) => a is Joints x ? b is Joints y && SameBits.Of(x, y) : b is null;
}

/// <summary>
/// A motion's solution for the state in <see cref="Key"/>: a Cartesian motion's joints (null: unreachable), or a joint move's TCP pose
/// (<see cref="Tcp"/>, its forward kinematics with the tool), and the kinematic issues.
/// </summary>
internal sealed record SolvedPose(PoseSolveKey Key, Joints? Axes, IReadOnlyList<KinematicIssue> Issues)
{
    private readonly StrongBox<Pose>? _tcp;

    /// <summary>A joint move's TCP pose; default for a Cartesian motion (kept apart: a line's solution has no room for it).</summary>
    internal Pose Tcp { get => _tcp?.Value ?? default; init => _tcp = new StrongBox<Pose>(value); }
}
