namespace Machina;

/// <summary>Closeness of a joint set to the three classic singularities (internal measure used by the checks).</summary>
/// <param name="WristDegrees">How far axis 5 is from the straight wrist (0° or 180°), in degrees.</param>
/// <param name="ElbowDegrees">How far the elbow is from fully stretched or fully folded, in degrees.</param>
/// <param name="ShoulderMm">How far the wrist point is from the axis-1 singular line/cylinder, in mm.</param>
internal readonly record struct SingularityMeasure(double WristDegrees, double ElbowDegrees, double ShoulderMm);

/// <summary>The raw analytical solver of one family: every solution, ignoring joint limits.</summary>
internal interface ISolver
{
    /// <summary>
    /// All geometric solutions (at most 8), brand joints in degrees wrapped to (−180°, 180°], with their configuration. At an exactly
    /// straight wrist, where axes 4 and 6 (UR: 6) are not determined by the pose, the free value is taken nearest to <paramref name="reference"/>.
    /// </summary>
    int SolveRaw(in Affine flange, in Joints reference, Span<Joints> joints, Span<ArmConfiguration> configurations);

    /// <summary>
    /// The solution <see cref="KinematicsCore.ClosestOf"/> picks from <see cref="SolveRaw"/>'s solutions for <paramref name="flange"/>
    /// with <paramref name="reference"/> (finite) as the reference and the solver's own model, to the bit; null when none is within
    /// the limits. <paramref name="reachable"/> is false when there is no raw solution at all. A solver may skip branches it can show
    /// are farther from the reference than one it solved.
    /// </summary>
    Joints? Closest(in Affine flange, in Joints reference, out bool reachable) =>
        KinematicsCore.ClosestOfAll(this, ((IKinematics)this).Model, flange, reference, out reachable);

    /// <summary>Closeness to singularities of a joint set.</summary>
    SingularityMeasure Measure(Joints joints);

    /// <summary>
    /// The configuration (<see cref="IKinematics.ConfigurationOf"/>) and <see cref="Measure"/> of one joint set, as those two give
    /// them: each sample of a checked path asks both, and a solver whose two share their sines computes them once.
    /// </summary>
    (ArmConfiguration Configuration, SingularityMeasure Measure) Assess(Joints joints) => (((IKinematics)this).ConfigurationOf(joints), Measure(joints));
}
