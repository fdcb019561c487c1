namespace Machina;

/// <summary>
/// One revolute joint of a serial arm as a row of a Denavit–Hartenberg table (for <see cref="RobotModel.FromDh"/>). Lengths in mm,
/// angles in degrees. The joint value θ (as the controller shows it) is added to <paramref name="ThetaOffset"/>.
/// </summary>
/// <param name="A">Link length a (mm): distance between this joint's axis and the next along their common normal
/// (with <see cref="DhConvention.Modified"/>: a<sub>i−1</sub>, the distance from the previous axis to this one).</param>
/// <param name="Alpha">Link twist α (degrees), the angle between the two axes (modified: α<sub>i−1</sub>).</param>
/// <param name="D">Link offset d (mm) along this joint's axis.</param>
/// <param name="ThetaOffset">Angle (degrees) added to the joint value, so that the table's θ = joint value + offset.</param>
public readonly record struct DhJoint(double A, double Alpha, double D, double ThetaOffset = 0);
