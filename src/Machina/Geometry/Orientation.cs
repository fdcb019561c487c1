namespace Machina;

/// <summary>
/// A frame orientation given by its X and Y axis directions, as in the original Machina (<c>new Orientation(-1,0,0, 0,1,0)</c>).
/// Y is made perpendicular to X and Z = X × Y. Converts implicitly to <see cref="Rotation"/>.
/// </summary>
public readonly struct Orientation : IEquatable<Orientation>
{
    /// <summary>The rotation that turns the world axes onto this frame's axes.</summary>
    public Rotation Rotation { get; }

    /// <summary>An orientation from its X and Y axis directions; refused when they are zero or parallel.</summary>
    public Orientation(Vector xAxis, Vector yAxis) => Rotation = Rotation.FromAxes(xAxis, yAxis);

    /// <summary>An orientation from X axis (x0, x1, x2) and Y axis (y0, y1, y2).</summary>
    public Orientation(double x0, double x1, double x2, double y0, double y1, double y2) =>
        Rotation = Rotation.FromAxes(new Vector(x0, x1, x2), new Vector(y0, y1, y2));

    /// <summary>An orientation from a rotation.</summary>
    public Orientation(Rotation rotation) => Rotation = rotation;

    /// <summary>The world XY frame (identity).</summary>
    public static Orientation WorldXY => new(Rotation.Identity);

    /// <summary>The world XZ frame: X axis (1, 0, 0), Y axis (0, 0, 1), so Z points along world −Y; as in the original.</summary>
    public static Orientation WorldXZ => new(1, 0, 0, 0, 0, 1);

    /// <summary>The world YZ frame: X axis (0, 1, 0), Y axis (0, 0, 1), so Z points along world +X; as in the original.</summary>
    public static Orientation WorldYZ => new(0, 1, 0, 0, 0, 1);

    /// <summary>The unit quaternion of this orientation.</summary>
    public Quaternion ToQuaternion() => Rotation.ToQuaternion();

    /// <summary>The 3×3 rotation matrix whose columns are this frame's axes.</summary>
    public RotationMatrix ToRotationMatrix() => Rotation.ToMatrix();

    /// <summary>Rotation vector (axis × angle, degrees) of this orientation.</summary>
    public RotationVector ToRotationVector() => Rotation.ToRotationVector();

    /// <summary>X axis of the frame.</summary>
    public Vector XAxis => Rotation.XAxis;

    /// <summary>Y axis of the frame.</summary>
    public Vector YAxis => Rotation.YAxis;

    /// <summary>Z axis of the frame.</summary>
    public Vector ZAxis => Rotation.ZAxis;

    /// <summary>The rotation of this orientation.</summary>
    public static implicit operator Rotation(Orientation o) => o.Rotation;

    /// <summary>The unit quaternion of this orientation, as in the original.</summary>
    public static implicit operator Quaternion(Orientation o) => o.Rotation.ToQuaternion();

    /// <summary>The rotation matrix of this orientation (its columns are the axes), as in the original.</summary>
    public static implicit operator RotationMatrix(Orientation o) => o.Rotation.ToMatrix();

    /// <summary>The orientation of a rotation.</summary>
    public static implicit operator Orientation(Rotation r) => new(r);

    /// <summary>Exact equality of the underlying rotations.</summary>
    public bool Equals(Orientation other) => Rotation == other.Rotation;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is Orientation o && Equals(o);

    /// <inheritdoc/>
    public override int GetHashCode() => Rotation.GetHashCode();

    /// <summary>Exact equality.</summary>
    public static bool operator ==(Orientation a, Orientation b) => a.Equals(b);

    /// <summary>Exact inequality.</summary>
    public static bool operator !=(Orientation a, Orientation b) => !a.Equals(b);

    /// <summary>Text of the axes <c>[[Xx, Xy, Xz], [Yx, Yy, Yz], [Zx, Zy, Zz]]</c> (3 decimals).</summary>
    public override string ToString() => Rotation.ToOrientationString();
}
