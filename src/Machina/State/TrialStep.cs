namespace Machina;

/// <summary>What trying one action in a <see cref="ProgramTrial"/> gave: refused with a reason, or applied with what deserves a look.</summary>
/// <param name="Action">The action tried.</param>
/// <param name="Refusal">Why it cannot be applied (the robot would refuse it), or null when it was applied.</param>
/// <param name="Warnings">Surprising but applied: e.g. a setting that rounds, a tool attached after the first move.</param>
/// <param name="Issues">What the arm cannot do or should not do for this motion (reach, joint limits, singularities, flips, joint speeds).</param>
public sealed record TrialStep(RobotAction Action, string? Refusal, IReadOnlyList<string> Warnings, IReadOnlyList<KinematicIssue> Issues)
{
    /// <summary>True when the action was applied (not refused).</summary>
    public bool Applied => Refusal is null;

    /// <summary>The estimated time the action takes on the controller (zero for one that takes none), or null when it was refused or is a motion that could not be timed (a pose or the joints were not known).</summary>
    public TimeSpan? Duration { get; init; }

    /// <summary>True when the action moves the robot.</summary>
    public bool IsMotion => ProgramTrial.IsMotion(Action);

    /// <summary>The first issue that makes the motion impossible (out of reach or beyond a joint's limit), or null.</summary>
    public KinematicIssue? Blocking => Issues.FirstOrDefault(i => i.Kind is KinematicIssueKind.Unreachable or KinematicIssueKind.JointLimit);
}
