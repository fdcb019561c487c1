namespace Machina.Simulation;

/// <summary>
/// Optional robot model for a virtual controller: turns joint angles into a TCP pose and back.
/// Without one, the virtual controller keeps joints and pose as separate values (a joint move changes only
/// the joints, a linear move only the pose).
/// </summary>
public interface IVirtualKinematics
{
    /// <summary>The flange pose (position in mm, orientation) for joint angles in degrees.</summary>
    (Vector Position, Rotation Rotation) Forward(Joints joints);

    /// <summary>Joint angles in degrees reaching the pose, closest to <paramref name="seed"/>; null when unreachable.</summary>
    Joints? Inverse(Vector position, Rotation rotation, Joints seed);
}
