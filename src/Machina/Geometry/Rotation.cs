namespace Machina;

/// <summary>
/// An orientation or turn in space, stored as a unit quaternion with the scalar part first (W, X, Y, Z).
/// <c>default</c> is the identity (no rotation); a zero or non-finite quaternion can never be created.
/// </summary>
public readonly struct Rotation : IEquatable<Rotation>
{
    private readonly double _w, _x, _y, _z;
    private readonly bool _set;

    private Rotation((double W, double X, double Y, double Z) q)
    {
        (_w, _x, _y, _z, _set) = (q.W, q.X, q.Y, q.Z, true);
    }

    private static Rotation Unit(double w, double x, double y, double z) => new((w, x, y, z));

    /// <summary>Scalar part of the quaternion.</summary>
    public double W => _set ? _w : 1.0;

    /// <summary>X component of the quaternion's vector part.</summary>
    public double X => _x;

    /// <summary>Y component of the quaternion's vector part.</summary>
    public double Y => _y;

    /// <summary>Z component of the quaternion's vector part.</summary>
    public double Z => _z;

    /// <summary>
    /// A rotation of <paramref name="angleDegrees"/> about <paramref name="axis"/> (right-hand rule), as in the original Machina;
    /// the same as <see cref="FromAxisAngle(Vector, double)"/>.
    /// </summary>
    public Rotation(Vector axis, double angleDegrees) => this = FromAxisAngle(axis, angleDegrees);

    /// <summary>A rotation of <paramref name="angleDegrees"/> about the axis (axisX, axisY, axisZ), as in the original Machina.</summary>
    public Rotation(double axisX, double axisY, double axisZ, double angleDegrees) => this = FromAxisAngle(axisX, axisY, axisZ, angleDegrees);

    /// <summary>No rotation.</summary>
    public static Rotation Identity => Unit(1, 0, 0, 0);

    /// <summary>No rotation (the original's name for <see cref="Identity"/>).</summary>
    public static Rotation GlobalXYZ => Identity;

    /// <summary>Half a turn about world X (tool Z pointing down, tool X along world +X).</summary>
    public static Rotation FlippedAroundX => Unit(0, 1, 0, 0);

    /// <summary>Half a turn about world Y: Machina's default flange orientation (tool Z down, tool X along world −X).</summary>
    public static Rotation FlippedAroundY => Unit(0, 0, 1, 0);

    /// <summary>Half a turn about world Z.</summary>
    public static Rotation FlippedAroundZ => Unit(0, 0, 0, 1);

    /// <summary>
    /// A rotation of <paramref name="degrees"/> about <paramref name="axis"/> (right-hand rule). The axis need not be unit length,
    /// but it must not be zero unless the angle is zero.
    /// </summary>
    public static Rotation FromAxisAngle(Vector axis, double degrees)
    {
        axis.RequireFinite(nameof(axis));
        Num.Finite(degrees, nameof(degrees));
        if (degrees == 0)
        {
            return Identity;
        }
        double length = axis.Length;
        if (double.IsPositiveInfinity(length))
        {
            // Finite but huge components overflow the squared length: only the direction matters.
            axis = axis.Normalized();
            length = 1;
        }
        if (length < 1e-9)
        {
            throw new ArgumentException($"The rotation axis {axis} has no direction; give a non-zero axis.", nameof(axis));
        }
        double half = degrees * Angles.ToRadians / 2;
        double s = Math.Sin(half) / length;
        return Unit(Math.Cos(half), axis.X * s, axis.Y * s, axis.Z * s);
    }

    /// <summary>A rotation of <paramref name="degrees"/> about the axis (x, y, z).</summary>
    public static Rotation FromAxisAngle(double x, double y, double z, double degrees) => FromAxisAngle(new Vector(x, y, z), degrees);

    /// <summary>A rotation from quaternion components (scalar first). The quaternion is scaled to unit length; a zero quaternion is refused.</summary>
    public static Rotation FromQuaternion(double w, double x, double y, double z)
    {
        if (!(double.IsFinite(w) && double.IsFinite(x) && double.IsFinite(y) && double.IsFinite(z)))
        {
            throw new ArgumentException("Quaternion components must be finite numbers.");
        }
        double n = Math.Sqrt(w * w + x * x + y * y + z * z);
        if (double.IsPositiveInfinity(n))
        {
            // Finite but huge components overflow the squared length: scale them down first.
            double scale = Math.Max(Math.Max(Math.Abs(w), Math.Abs(x)), Math.Max(Math.Abs(y), Math.Abs(z)));
            w /= scale; x /= scale; y /= scale; z /= scale;
            n = Math.Sqrt(w * w + x * x + y * y + z * z);
        }
        if (n < 1e-9)
        {
            throw new ArgumentException("A zero quaternion does not describe a rotation.");
        }
        if (Math.Abs(n - 1) < 1e-15)
        {
            return Unit(w, x, y, z);
        }
        return Unit(w / n, x / n, y / n, z / n);
    }

    /// <summary>
    /// The frame whose X axis points along <paramref name="xAxis"/> and whose Y axis lies in the plane of the two vectors
    /// (Y is made perpendicular to X; Z = X × Y). Refused when the vectors are zero or parallel.
    /// </summary>
    public static Rotation FromAxes(Vector xAxis, Vector yAxis)
    {
        xAxis.RequireFinite(nameof(xAxis));
        yAxis.RequireFinite(nameof(yAxis));
        if (xAxis.Length < 1e-9 || yAxis.Length < 1e-9)
        {
            throw new ArgumentException($"Cannot build a frame from X {xAxis} and Y {yAxis}: an axis is zero.", xAxis.Length < 1e-9 ? nameof(xAxis) : nameof(yAxis));
        }
        Vector nx = xAxis.Normalized();
        Vector zc = Vector.Cross(nx, yAxis);
        if (zc.Length < 1e-9 * yAxis.Length)
        {
            throw new ArgumentException($"Cannot build a frame from X {xAxis} and Y {yAxis}: the axes are parallel.", nameof(yAxis));
        }
        Vector nz = zc.Normalized();
        Vector ny = Vector.Cross(nz, nx);
        return RotationMatrix.FromColumnsUnchecked(nx, ny, nz).ToRotation();
    }

    /// <summary>The frame with axes (x0, x1, x2) and (y0, y1, y2); see <see cref="FromAxes(Vector, Vector)"/>.</summary>
    public static Rotation FromAxes(double x0, double x1, double x2, double y0, double y1, double y2) =>
        FromAxes(new Vector(x0, x1, x2), new Vector(y0, y1, y2));

    /// <summary>A rotation from a rotation vector (axis × angle, angle in degrees).</summary>
    public static Rotation FromRotationVector(Vector rotationVectorDegrees)
    {
        rotationVectorDegrees.RequireFinite(nameof(rotationVectorDegrees));
        double angle = rotationVectorDegrees.Length;
        return angle == 0 ? Identity : FromAxisAngle(rotationVectorDegrees / angle, angle);
    }

    /// <summary>A rotation from intrinsic Z-Y′-X″ Euler angles in degrees: first yaw about Z, then pitch about the new Y, then roll about the new X.</summary>
    public static Rotation FromYawPitchRoll(double yaw, double pitch, double roll) => new YawPitchRoll(roll, pitch, yaw).ToRotation();

    internal static Rotation FromUnitQuaternionUnchecked(double w, double x, double y, double z) => Unit(w, x, y, z);

    /// <summary>X axis of the rotated frame (first column of the rotation matrix).</summary>
    public Vector XAxis => new(1 - 2 * (Y * Y + Z * Z), 2 * (X * Y + W * Z), 2 * (X * Z - W * Y));

    /// <summary>Y axis of the rotated frame (second column of the rotation matrix).</summary>
    public Vector YAxis => new(2 * (X * Y - W * Z), 1 - 2 * (X * X + Z * Z), 2 * (Y * Z + W * X));

    /// <summary>Z axis of the rotated frame (third column of the rotation matrix); for a robot TCP, the tool direction.</summary>
    public Vector ZAxis => new(2 * (X * Z + W * Y), 2 * (Y * Z - W * X), 1 - 2 * (X * X + Y * Y));

    /// <summary>The opposite rotation.</summary>
    public Rotation Inverse() => Unit(W, -X, -Y, -Z);

    /// <summary>The opposite rotation of <paramref name="r"/> (the original's static form of <see cref="Inverse()"/>).</summary>
    public static Rotation Inverse(Rotation r) => r.Inverse();

    /// <summary>
    /// Unit axis of this rotation (see <see cref="ToAxisAngle"/>): with <see cref="Angle"/> in [0°, 180°]; a zero vector for the identity.
    /// The original kept the axis and angle as given (<c>(0,0,1), −90°</c>); this is the same rotation as <c>(0,0,−1), 90°</c>.
    /// </summary>
    public Vector Axis => ToAxisAngle().Axis;

    /// <summary>Angle of this rotation about <see cref="Axis"/>, in degrees, in [0°, 180°].</summary>
    public double Angle => ToAxisAngle().Angle;

    /// <summary>The unit quaternion (W, X, Y, Z) of this rotation.</summary>
    public Quaternion ToQuaternion() => new(W, X, Y, Z);

    /// <summary>A rotation from a quaternion; it is scaled to unit length, and a zero quaternion is refused.</summary>
    public static Rotation FromQuaternion(Quaternion q) => FromQuaternion(q.W, q.X, q.Y, q.Z);

    /// <summary>The orientation (frame axes) of this rotation.</summary>
    public Orientation ToOrientation() => new(this);

    /// <summary>
    /// Composition: <c>a * b</c> applies <c>b</c> in the frame of <c>a</c> (local); equivalently, <c>b</c> first and then <c>a</c> in world axes.
    /// </summary>
    public static Rotation operator *(Rotation a, Rotation b)
    {
        double aw = a.W, ax = a.X, ay = a.Y, az = a.Z, bw = b.W, bx = b.X, by = b.Y, bz = b.Z;
        double w = aw * bw - ax * bx - ay * by - az * bz;
        double x = aw * bx + ax * bw + ay * bz - az * by;
        double y = aw * by - ax * bz + ay * bw + az * bx;
        double z = aw * bz + ax * by - ay * bx + az * bw;
        // Keep unit length despite rounding drift over long chains of relative rotations.
        double n = w * w + x * x + y * y + z * z;
        if (Math.Abs(n - 1) > 1e-14)
        {
            double inv = 1 / Math.Sqrt(n);
            w *= inv; x *= inv; y *= inv; z *= inv;
        }
        return Unit(w, x, y, z);
    }

    /// <summary>Rotates a vector by this rotation.</summary>
    public static Vector operator *(Rotation q, Vector v) => q.Rotate(v);

    /// <summary>Rotates a vector by this rotation.</summary>
    public Vector Rotate(Vector v)
    {
        double w = W;
        // t = 2 (q × v); v' = v + w t + q × t
        double tx = 2 * (Y * v.Z - Z * v.Y);
        double ty = 2 * (Z * v.X - X * v.Z);
        double tz = 2 * (X * v.Y - Y * v.X);
        return new Vector(
            v.X + w * tx + (Y * tz - Z * ty),
            v.Y + w * ty + (Z * tx - X * tz),
            v.Z + w * tz + (X * ty - Y * tx));
    }

    /// <summary>r1 then r2 measured in r1's own axes: <c>r1 * r2</c>.</summary>
    public static Rotation Combine(Rotation r1, Rotation r2) => r1 * r2;

    /// <summary>r2 applied in world axes after r1: <c>r2 * r1</c>.</summary>
    public static Rotation Global(Rotation r1, Rotation r2) => r2 * r1;

    /// <summary>r2 applied in r1's local axes: <c>r1 * r2</c>.</summary>
    public static Rotation Local(Rotation r1, Rotation r2) => r1 * r2;

    /// <summary>Axis and angle of this rotation, with the angle in [0°, 180°]. The identity gives a zero axis and angle 0.</summary>
    public AxisAngle ToAxisAngle()
    {
        double w = W, x = X, y = Y, z = Z;
        if (w < 0)
        {
            w = -w; x = -x; y = -y; z = -z;
        }
        double s = Math.Sqrt(x * x + y * y + z * z);
        if (s == 0)
        {
            return new AxisAngle(Vector.Zero, 0);
        }
        double angle = 2 * Math.Atan2(s, w) * Angles.ToDegrees;
        return new AxisAngle(new Vector(x / s, y / s, z / s), angle);
    }

    /// <summary>Rotation vector (unit axis × angle), in degrees, with length in [0, 180].</summary>
    public RotationVector ToRotationVector()
    {
        AxisAngle aa = ToAxisAngle();
        return new RotationVector(aa.Axis.X * aa.Angle, aa.Axis.Y * aa.Angle, aa.Axis.Z * aa.Angle);
    }

    /// <summary>The 3×3 rotation matrix whose columns are the frame axes.</summary>
    public RotationMatrix ToMatrix() => RotationMatrix.FromColumnsUnchecked(XAxis, YAxis, ZAxis);

    /// <summary>Intrinsic Z-Y′-X″ Euler angles in degrees (pitch in [−90°, 90°]).</summary>
    /// <remarks>
    /// Every <see cref="Rotation"/> is a unit quaternion (to ~1e-14: each way of making one scales it), so its matrix is a rotation far
    /// within <see cref="RotationMatrix.IsRotation"/>'s 1e-6 and is not checked again (a KUKA position's A, B and C at every motion).
    /// </remarks>
    public YawPitchRoll ToYawPitchRoll() => ToMatrix().YawPitchRollOfRotation();

    /// <summary>True when both describe the same rotation within <paramref name="toleranceDegrees"/> (q and −q are the same rotation).</summary>
    public bool IsSimilar(Rotation other, double toleranceDegrees = 1e-6) => AngleTo(other) <= toleranceDegrees;

    /// <summary>The angle in degrees of the smallest turn that takes this rotation onto <paramref name="other"/>.</summary>
    public double AngleTo(Rotation other)
    {
        if (W == other.W && X == other.X && Y == other.Y && Z == other.Z)
        {
            // The same rotation (every move of a toolpath that keeps its orientation): the formula below gives exactly 0.
            return 0;
        }
        // Relative rotation d = this⁻¹ · other, measured with atan2 for precision at tiny angles.
        double aw = W, ax = -X, ay = -Y, az = -Z, bw = other.W, bx = other.X, by = other.Y, bz = other.Z;
        double w = aw * bw - ax * bx - ay * by - az * bz;
        double x = aw * bx + ax * bw + ay * bz - az * by;
        double y = aw * by - ax * bz + ay * bw + az * bx;
        double z = aw * bz + ax * by - ay * bx + az * bw;
        return 2 * Math.Atan2(Math.Sqrt(x * x + y * y + z * z), Math.Abs(w)) * Angles.ToDegrees;
    }

    /// <summary>Exact component equality.</summary>
    public bool Equals(Rotation other) => W == other.W && X == other.X && Y == other.Y && Z == other.Z;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is Rotation r && Equals(r);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(W, X, Y, Z);

    /// <summary>Exact component equality.</summary>
    public static bool operator ==(Rotation a, Rotation b) => a.Equals(b);

    /// <summary>Exact component inequality.</summary>
    public static bool operator !=(Rotation a, Rotation b) => !a.Equals(b);

    /// <summary>Quaternion text <c>[w, x, y, z]</c> with 4 decimals, as RAPID prints it.</summary>
    public string ToQuaternionString() => $"[{Num.F(W, 4)}, {Num.F(X, 4)}, {Num.F(Y, 4)}, {Num.F(Z, 4)}]";

    /// <summary>Text of the frame axes <c>[[Xx, Xy, Xz], [Yx, Yy, Yz], [Zx, Zy, Zz]]</c> (3 decimals).</summary>
    public string ToOrientationString() => $"[{XAxis}, {YAxis}, {ZAxis}]";

    /// <summary>Quaternion text, e.g. <c>Rotation[w, x, y, z]</c>.</summary>
    public override string ToString() => "Rotation" + ToQuaternionString();
}
