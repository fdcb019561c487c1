namespace Machina;

/// <summary>A rotation described as a unit axis and an angle in degrees (right-hand rule).</summary>
/// <param name="Axis">Direction of the rotation axis; zero only for the identity.</param>
/// <param name="Angle">Angle in degrees.</param>
public readonly record struct AxisAngle(Vector Axis, double Angle)
{
    /// <summary>The rotation this axis and angle describe.</summary>
    public Rotation ToRotation() => Angle == 0 || Axis == Vector.Zero ? Rotation.Identity : Rotation.FromAxisAngle(Axis, Angle);

    /// <summary>The unit quaternion of this rotation.</summary>
    public Quaternion ToQuaternion() => ToRotation().ToQuaternion();

    /// <summary>The 3×3 rotation matrix of this rotation.</summary>
    public RotationMatrix ToRotationMatrix() => ToRotation().ToMatrix();

    /// <summary>Intrinsic Z-Y′-X″ Euler angles in degrees of this rotation.</summary>
    public YawPitchRoll ToYawPitchRoll() => ToRotation().ToYawPitchRoll();

    /// <summary>
    /// The unit axis times the angle as given (not reduced to [0°, 180°]), in degrees, or in radians when <paramref name="radians"/>
    /// is true; as in the original. A zero axis gives the zero vector.
    /// </summary>
    public RotationVector ToRotationVector(bool radians = false)
    {
        Vector v = Axis == Vector.Zero ? Vector.Zero : Axis.Normalized() * (radians ? Angle * Angles.ToRadians : Angle);
        return new RotationVector(v.X, v.Y, v.Z);
    }

    /// <summary>The same rotation with a unit axis: the identity's zero axis becomes Z (an instruction cannot name a zero axis).</summary>
    internal AxisAngle WithUnitAxis() => Axis == Vector.Zero ? new AxisAngle(Vector.ZAxis, 0) : this;

    /// <summary>Text such as <c>AxisAngle[0, 1, 0, 90]</c> (3 decimals).</summary>
    public override string ToString() => $"AxisAngle[{Num.F(Axis.X, 3)}, {Num.F(Axis.Y, 3)}, {Num.F(Axis.Z, 3)}, {Num.F(Angle, 3)}]";
}

/// <summary>A rotation described as a vector along its axis whose length is the angle in degrees (the form Universal Robots use, there in radians).</summary>
/// <param name="X">X component (degrees).</param>
/// <param name="Y">Y component (degrees).</param>
/// <param name="Z">Z component (degrees).</param>
public readonly record struct RotationVector(double X, double Y, double Z)
{
    /// <summary>
    /// A rotation vector from an axis direction (any length) and an angle, as in the original: the unit axis times
    /// <paramref name="angle"/>. A zero axis gives the zero vector.
    /// </summary>
    public RotationVector(double x, double y, double z, double angle) : this(Scaled(x, y, z, angle))
    {
    }

    private RotationVector(Vector v) : this(v.X, v.Y, v.Z)
    {
    }

    private static Vector Scaled(double x, double y, double z, double angle)
    {
        var axis = new Vector(x, y, z);
        axis.RequireFinite(nameof(axis));
        Num.Finite(angle, nameof(angle));
        return axis.Length < 1e-12 ? Vector.Zero : axis.Normalized() * angle;
    }

    /// <summary>The angle in degrees (the vector's length).</summary>
    public double Angle => Math.Sqrt(X * X + Y * Y + Z * Z);

    /// <summary>The angle in degrees (the vector's length), the original's name for <see cref="Angle"/>.</summary>
    public double GetAngle() => Angle;

    /// <summary>The length of the vector (the angle in degrees), as in the original.</summary>
    public double Length() => Angle;

    /// <summary>The squared length of the vector, as in the original.</summary>
    public double SqLength() => X * X + Y * Y + Z * Z;

    /// <summary>True when the squared length is below 1e-6 (no rotation), as in the original.</summary>
    public bool IsZero() => SqLength() < 1e-6;

    /// <summary>The unit axis of this vector (zero for the zero vector), as in the original.</summary>
    public Vector GetVector() => ToAxisAngle().Axis;

    /// <summary>The axis (unit length) and angle (the vector's length) of this vector; the zero vector gives a zero axis and angle 0.</summary>
    public AxisAngle ToAxisAngle()
    {
        double angle = Angle;
        return angle < 1e-12 ? new AxisAngle(Vector.Zero, 0) : new AxisAngle(new Vector(X / angle, Y / angle, Z / angle), angle);
    }

    /// <summary>The 3×3 rotation matrix of the rotation this vector describes.</summary>
    public RotationMatrix ToRotationMatrix() => ToRotation().ToMatrix();

    /// <summary>Intrinsic Z-Y′-X″ Euler angles in degrees of the rotation this vector describes.</summary>
    public YawPitchRoll ToYawPitchRoll() => ToRotation().ToYawPitchRoll();

    /// <summary>The rotation this vector describes.</summary>
    public Rotation ToRotation() => Rotation.FromRotationVector(new Vector(X, Y, Z));

    /// <summary>The unit quaternion of the rotation this vector describes.</summary>
    public Quaternion ToQuaternion() => ToRotation().ToQuaternion();

    /// <summary>The same vector with components in radians.</summary>
    public Vector ToRadians() => new(X * Angles.ToRadians, Y * Angles.ToRadians, Z * Angles.ToRadians);

    /// <summary>Text such as <c>RotationVector[0, 90, 0]</c> (3 decimals).</summary>
    public override string ToString() => $"RotationVector[{Num.F(X, 3)}, {Num.F(Y, 3)}, {Num.F(Z, 3)}]";
}
