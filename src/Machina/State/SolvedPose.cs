namespace Machina;

/// <summary>
/// Everything a cursor's inverse kinematics reads for one Cartesian motion: the model, the joints before it, the TCP target, the
/// tool, an arc's through point, the motion type and the speed. Equal keys give the same joints and the same issues.
/// </summary>
internal readonly record struct PoseSolveKey(
    RobotModel Model, Joints? PrevAxes, Vector Position, Rotation Rotation, Tool? Tool, Vector? Through, Rotation? ThroughRotation,
    MotionType MotionType, double Speed);

/// <summary>A motion's solved joints (null: unreachable) and kinematic issues, for the state in <see cref="Key"/>.</summary>
internal sealed record SolvedPose(PoseSolveKey Key, Joints? Axes, IReadOnlyList<KinematicIssue> Issues);
