namespace Machina;

/// <summary>
/// Forward and inverse kinematics of one robot model: joints (degrees, as the brand's controller shows them) to flange pose
/// (mm, in the brand's base frame) and back. Obtain it with <see cref="RobotModel.Kinematics"/>.
/// </summary>
public interface IKinematics
{
    /// <summary>The robot model these kinematics belong to.</summary>
    RobotModel Model { get; }

    /// <summary>The flange pose (tool0 / FLANGE) in the robot base frame for the given joint values in degrees.</summary>
    Pose Forward(Joints joints);

    /// <summary>
    /// Writes every joint solution for the flange pose that respects the joint limits into <paramref name="solutions"/> (pass room for 8)
    /// and returns how many were written. Allocation-free. Angles are picked within the limits, closest to 0.
    /// </summary>
    int Inverse(Pose flange, Span<Joints> solutions);

    /// <summary>Every joint solution for the flange pose that respects the joint limits (empty when unreachable).</summary>
    IReadOnlyList<Joints> Inverse(Pose flange);

    /// <summary>
    /// Like <see cref="Inverse(Pose)"/>, plus the other turns: every ±360° variant of each joint that stays within the limits
    /// (axes with a range over 360°, such as ABB axis 6 at ±400° or every UR axis at ±360°, reach one pose several ways).
    /// </summary>
    IReadOnlyList<Joints> InverseAllTurns(Pose flange) => KinematicsCore.WithEveryTurn(Model, Inverse(flange));

    /// <summary>
    /// The solution nearest to <paramref name="current"/> joints (largest single-joint change is minimised; each joint takes the ±360°
    /// turn that is closest), or null when the pose cannot be reached within the limits.
    /// </summary>
    Joints? Closest(Pose flange, Joints current);

    /// <summary>The solution with the requested configuration, or null when that configuration cannot reach the pose within the limits.</summary>
    Joints? Solve(Pose flange, ArmConfiguration configuration);

    /// <summary>
    /// Why <see cref="Inverse(Pose)"/> (and <see cref="Closest"/>) find no solution for this flange pose, or null when they find one:
    /// <see cref="KinematicIssueKind.Unreachable"/> when the pose is out of the arm's reach, <see cref="KinematicIssueKind.JointLimit"/>
    /// when it is reachable only with a joint beyond its limits (then <see cref="KinematicIssue.Joint"/> and
    /// <see cref="KinematicIssue.Limit"/> name the limit passed by the way of reaching it that comes nearest to being allowed).
    /// </summary>
    KinematicIssue? WhyNoSolution(Pose flange);

    /// <summary>The shoulder/elbow/wrist configuration of a set of joint values.</summary>
    ArmConfiguration ConfigurationOf(Joints joints);

    /// <summary>True when every joint is within the model's limits.</summary>
    bool IsWithinLimits(Joints joints);
}
