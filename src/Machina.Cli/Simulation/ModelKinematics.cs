using Machina.Simulation;

namespace Machina.Cli.Simulation;

/// <summary>Lets a virtual controller move like a catalogued arm: joints and pose kept in step by the model's kinematics.</summary>
internal sealed class ModelKinematics(RobotModel model) : IVirtualKinematics
{
    /// <inheritdoc/>
    public (Vector Position, Rotation Rotation) Forward(Joints joints)
    {
        Pose flange = model.Kinematics.Forward(joints);
        return (flange.Position, flange.Rotation);
    }

    /// <inheritdoc/>
    public Joints? Inverse(Vector position, Rotation rotation, Joints seed) => model.Kinematics.Closest(new Pose(position, rotation), seed);
}
