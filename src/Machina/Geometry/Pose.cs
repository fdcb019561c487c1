namespace Machina;

/// <summary>
/// A position (mm) and an orientation together: where a frame is and how it is turned, e.g. a robot flange in the base frame.
/// <c>default</c> is the identity pose (origin, no rotation).
/// </summary>
/// <param name="Position">Origin of the frame, in millimetres.</param>
/// <param name="Rotation">Orientation of the frame.</param>
public readonly record struct Pose(Vector Position, Rotation Rotation)
{
    /// <summary>The identity pose: at the origin, not rotated.</summary>
    public static Pose Identity => default;

    /// <summary>A pose from a position in mm and a rotation.</summary>
    public Pose(double x, double y, double z, Rotation rotation) : this(new Vector(x, y, z), rotation) { }

    /// <summary>
    /// Composition: <c>a * b</c> is the pose <c>b</c> expressed in the frame of <c>a</c>, brought to the frame <c>a</c> lives in
    /// (e.g. <c>flange * tool</c> gives the tool tip in the base frame).
    /// </summary>
    public static Pose operator *(Pose a, Pose b) => new(a.Position + a.Rotation.Rotate(b.Position), a.Rotation * b.Rotation);

    /// <summary>The opposite pose: <c>p * p.Inverse()</c> is the identity.</summary>
    public Pose Inverse()
    {
        Rotation inv = Rotation.Inverse();
        return new Pose(-inv.Rotate(Position), inv);
    }

    /// <summary>Maps a point given in this frame to the outer frame (rotate, then move).</summary>
    public Vector Transform(Vector point) => Position + Rotation.Rotate(point);

    /// <summary>True when the positions differ by less than <paramref name="mmTolerance"/> per axis and the rotations by less than <paramref name="degreesTolerance"/>.</summary>
    public bool IsSimilar(Pose other, double mmTolerance = 1e-6, double degreesTolerance = 1e-6) =>
        Position.IsSimilar(other.Position, mmTolerance) && Rotation.IsSimilar(other.Rotation, degreesTolerance);

    /// <summary>Text such as <c>Pose[[374, 0, 630], [0.7071, 0, 0.7071, 0]]</c> (quaternion W first).</summary>
    public override string ToString() => $"Pose[{Position}, {Rotation.ToQuaternionString()}]";
}
