namespace Machina;

/// <summary>What a controller reports when a connection opens: its driver version and where the robot is.</summary>
/// <param name="Version">Driver version text, such as "1.4.2".</param>
/// <param name="Position">Flange position in mm, or null when not reported.</param>
/// <param name="Rotation">Flange orientation, or null when not reported.</param>
/// <param name="Axes">Joint angles in degrees, or null when not reported.</param>
/// <param name="ExternalAxes">External axis values, or null when the robot has none.</param>
internal sealed record DeviceHandshake(string Version, Vector? Position, Rotation? Rotation, Joints? Axes, ExternalAxes? ExternalAxes);

/// <summary>One live pose report from the controller (ABB monitor <c>$24</c>).</summary>
internal readonly record struct MotionSample(Vector Position, Rotation Rotation, Joints Axes, ExternalAxes? ExternalAxes);
