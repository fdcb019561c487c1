namespace Machina;

/// <summary>A rotation described as a unit axis and an angle in degrees (right-hand rule).</summary>
/// <param name="Axis">Direction of the rotation axis; zero only for the identity.</param>
/// <param name="Angle">Angle in degrees.</param>
public readonly record struct AxisAngle(Vector Axis, double Angle)
{
    /// <summary>The rotation this axis and angle describe.</summary>
    public Rotation ToRotation() => Angle == 0 || Axis == Vector.Zero ? Rotation.Identity : Rotation.FromAxisAngle(Axis, Angle);

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
    /// <summary>The angle in degrees (the vector's length).</summary>
    public double Angle => Math.Sqrt(X * X + Y * Y + Z * Z);

    /// <summary>The rotation this vector describes.</summary>
    public Rotation ToRotation() => Rotation.FromRotationVector(new Vector(X, Y, Z));

    /// <summary>The same vector with components in radians.</summary>
    public Vector ToRadians() => new(X * Angles.ToRadians, Y * Angles.ToRadians, Z * Angles.ToRadians);

    /// <summary>Text such as <c>RotationVector[0, 90, 0]</c> (3 decimals).</summary>
    public override string ToString() => $"RotationVector[{Num.F(X, 3)}, {Num.F(Y, 3)}, {Num.F(Z, 3)}]";
}
