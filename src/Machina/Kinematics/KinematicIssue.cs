namespace Machina;

/// <summary>What kind of problem a pre-flight kinematic check found.</summary>
public enum KinematicIssueKind
{
    /// <summary>The target (or a point on the way) is out of the arm's reach.</summary>
    Unreachable,

    /// <summary>Reaching the target (or a point on the way) needs a joint beyond its limits.</summary>
    JointLimit,

    /// <summary>Axis 5 is (nearly) straight, so axes 4 and 6 line up and can spin fast.</summary>
    WristSingularity,

    /// <summary>The wrist point is (nearly) on axis 1's singular line, so axis 1 can spin fast.</summary>
    ShoulderSingularity,

    /// <summary>The arm is (nearly) fully stretched or folded at the elbow.</summary>
    ElbowSingularity,

    /// <summary>A straight-line move would need the arm to change shoulder, elbow or wrist configuration, which it cannot do on a line.</summary>
    ConfigurationFlip,

    /// <summary>At the requested speed a joint would have to move faster than its maximum speed.</summary>
    JointSpeed,

    /// <summary>A joint move to a Cartesian target swings one joint by more than half a turn, often a surprise for the tool and its cables.</summary>
    LargeJointMove,
}

/// <summary>How the robot moves to the target, for the checks.</summary>
public enum KinematicMotion
{
    /// <summary>Straight line of the tool tip (MoveL, LIN, movel).</summary>
    Linear,

    /// <summary>Joint interpolation (MoveJ, PTP, movej): the path is not a line.</summary>
    Joint,
}

/// <summary>One problem found by <see cref="KinematicChecks"/>, with a sentence a non-expert can read.</summary>
/// <param name="Kind">The kind of problem.</param>
/// <param name="Reason">Human explanation, e.g. which joint and by how much.</param>
public sealed record KinematicIssue(KinematicIssueKind Kind, string Reason)
{
    /// <summary>For a <see cref="KinematicIssueKind.JointLimit"/> issue, the joint (1 to 6) furthest past its limit; otherwise null.</summary>
    public int? Joint { get; init; }

    /// <summary>For a <see cref="KinematicIssueKind.JointLimit"/> issue, the limit of <see cref="Joint"/> that is passed, degrees; otherwise null.</summary>
    public double? Limit { get; init; }

    /// <summary>Text such as <c>JointLimit: joint 3 would be at 95° (limit 70°)</c>.</summary>
    public override string ToString() => $"{Kind}: {Reason}";
}
