namespace Machina;

/// <summary>The kind of arm geometry, which decides the inverse-kinematics solver.</summary>
public enum KinematicFamily
{
    /// <summary>Ortho-parallel arm with a spherical wrist (ABB, KUKA): seven OPW lengths.</summary>
    Opw,

    /// <summary>Universal Robots layout (offset wrist): six DH lengths.</summary>
    UniversalRobots,

    /// <summary>Any six-joint serial arm described by a Denavit–Hartenberg table (<see cref="RobotModel.FromDh"/>); numerical inverse.</summary>
    Dh,
}
