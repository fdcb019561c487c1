namespace Machina;

/// <summary>
/// One motion as a controller times it: where the tool and the joints start and end, how long the tool's path is, and the
/// program's speed (mm/s, or deg/s for joint speeds and turns) and acceleration (mm/s²; 0 or Machina's default = the
/// controller's own) in force for it.
/// </summary>
internal readonly record struct TimedMotion(
    Vector? FromPosition, Rotation? FromRotation, Joints? FromJoints,
    Vector? ToPosition, Rotation? ToRotation, Joints? ToJoints,
    double? PathMm, bool IsJoint, double Speed, double Acceleration)
{
    /// <summary>The tool's path in mm: the cursor's path length (arcs included), else the straight line, or null while a pose is unknown.</summary>
    internal double? Millimetres => PathMm ?? (FromPosition is Vector a && ToPosition is Vector b ? Vector.Distance(a, b) : null);

    /// <summary>How far the tool turns, degrees, or null while an orientation is unknown.</summary>
    internal double? TurnDegrees => FromRotation is Rotation a && ToRotation is Rotation b ? a.AngleTo(b) : null;

    /// <summary>The largest joint travel, degrees, or null while the joints are unknown.</summary>
    internal double? LargestJointTravel => FromJoints is Joints a && ToJoints is Joints b ? (b - a).ToArray().Max(Math.Abs) : null;

    /// <summary>True when the program asks for the controller's own acceleration.</summary>
    internal bool ControllerAcceleration => Settings.MeansControllerAcceleration(Acceleration);
}
