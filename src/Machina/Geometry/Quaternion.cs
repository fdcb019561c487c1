namespace Machina;

/// <summary>
/// Four numbers W, X, Y, Z (scalar first), as in the original Machina: quaternion arithmetic and conversions. A unit quaternion
/// is a rotation; <see cref="ToRotation"/> turns any non-zero one into a <see cref="Rotation"/>. Both <c>new Quaternion()</c> and
/// <c>default</c> are the identity (1, 0, 0, 0). Unlike the original it is an immutable value: operations return a new quaternion.
/// </summary>
public readonly struct Quaternion : IEquatable<Quaternion>
{
    private readonly double _w, _x, _y, _z;
    private readonly bool _set;

    /// <summary>The identity (1, 0, 0, 0), as in the original.</summary>
    public Quaternion() => (_w, _set) = (1, true);

    /// <summary>A quaternion from its components, kept exactly as given (the original rescaled the vector part).</summary>
    public Quaternion(double w, double x, double y, double z)
    {
        if (!(double.IsFinite(w) && double.IsFinite(x) && double.IsFinite(y) && double.IsFinite(z)))
        {
            throw new ArgumentException($"Quaternion components must be finite numbers, not ({w}, {x}, {y}, {z}).");
        }
        (_w, _x, _y, _z, _set) = (w, x, y, z, true);
    }

    /// <summary>Scalar part.</summary>
    public double W => _set ? _w : 1.0;

    /// <summary>X component of the vector part.</summary>
    public double X => _x;

    /// <summary>Y component of the vector part.</summary>
    public double Y => _y;

    /// <summary>Z component of the vector part.</summary>
    public double Z => _z;

    /// <summary>The identity quaternion (1, 0, 0, 0): no rotation.</summary>
    public static Quaternion Identity => new();

    /// <summary>Length (norm) of the quaternion.</summary>
    public double Length() => Math.Sqrt(SqLength());

    /// <summary>Squared length of the quaternion.</summary>
    public double SqLength() => W * W + X * X + Y * Y + Z * Z;

    /// <summary>True when the length is 1 (within 1e-6 on the squared length), i.e. the quaternion is a rotation.</summary>
    public bool IsUnit() => Math.Abs(SqLength() - 1) < 1e-6;

    /// <summary>True when the squared length is below 1e-6.</summary>
    public bool IsZero() => SqLength() < 1e-6;

    /// <summary>True when this is ±(1, 0, 0, 0) within 1e-6: no rotation.</summary>
    public bool IsIdentity() => Math.Abs(Math.Abs(W) - 1) < 1e-6 && Math.Abs(X) < 1e-6 && Math.Abs(Y) < 1e-6 && Math.Abs(Z) < 1e-6;

    /// <summary>True when every component is within 1e-6 of <paramref name="other"/>'s.</summary>
    public bool IsSimilar(Quaternion other) =>
        Math.Abs(W - other.W) < 1e-6 && Math.Abs(X - other.X) < 1e-6 && Math.Abs(Y - other.Y) < 1e-6 && Math.Abs(Z - other.Z) < 1e-6;

    /// <summary>True when both describe the same rotation (q and −q do), whatever their lengths; zero quaternions are never equivalent.</summary>
    public bool IsEquivalent(Quaternion other)
    {
        double la = Length(), lb = other.Length();
        if (la < 1e-9 || lb < 1e-9)
        {
            return false;
        }
        double dot = (W * other.W + X * other.X + Y * other.Y + Z * other.Z) / (la * lb);
        return Math.Abs(Math.Abs(dot) - 1) < 1e-6;
    }

    /// <summary>The rotation this quaternion describes, after scaling it to unit length. A zero quaternion is refused.</summary>
    public Rotation ToRotation() => Rotation.FromQuaternion(W, X, Y, Z);

    /// <summary>Axis and angle (degrees, in [0°, 180°]) of the rotation; see <see cref="ToRotation"/>.</summary>
    public AxisAngle ToAxisAngle() => ToRotation().ToAxisAngle();

    /// <summary>The 3×3 rotation matrix of the rotation; see <see cref="ToRotation"/>.</summary>
    public RotationMatrix ToRotationMatrix() => ToRotation().ToMatrix();

    /// <summary>Intrinsic Z-Y′-X″ Euler angles in degrees of the rotation; see <see cref="ToRotation"/>.</summary>
    public YawPitchRoll ToYawPitchRoll() => ToRotation().ToYawPitchRoll();

    /// <summary>Rotation vector (axis × angle) of the rotation, in degrees, or in radians when <paramref name="radians"/> is true.</summary>
    public RotationVector ToRotationVector(bool radians = false)
    {
        RotationVector v = ToRotation().ToRotationVector();
        return radians ? new RotationVector(v.X * Angles.ToRadians, v.Y * Angles.ToRadians, v.Z * Angles.ToRadians) : v;
    }

    /// <summary>The rotation of a unit quaternion; see <see cref="ToRotation"/> (explicit, because a zero quaternion is refused).</summary>
    public static explicit operator Rotation(Quaternion q) => q.ToRotation();

    /// <summary>The unit quaternion of a rotation.</summary>
    public static implicit operator Quaternion(Rotation r) => new(r.W, r.X, r.Y, r.Z);

    /// <summary>Component-wise sum.</summary>
    public static Quaternion operator +(Quaternion a, Quaternion b) => new(a.W + b.W, a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    /// <summary>Component-wise difference.</summary>
    public static Quaternion operator -(Quaternion a, Quaternion b) => new(a.W - b.W, a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    /// <summary>Hamilton product: <c>a * b</c> applies <c>b</c> in the frame of <c>a</c> (as <see cref="Rotation"/>'s <c>*</c>).</summary>
    public static Quaternion operator *(Quaternion a, Quaternion b) => new(
        a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z,
        a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
        a.W * b.Y - a.X * b.Z + a.Y * b.W + a.Z * b.X,
        a.W * b.Z + a.X * b.Y - a.Y * b.X + a.Z * b.W);

    /// <summary>Every component times <paramref name="factor"/>.</summary>
    public static Quaternion operator *(Quaternion q, double factor) => new(q.W * factor, q.X * factor, q.Y * factor, q.Z * factor);

    /// <summary>Every component times <paramref name="factor"/>.</summary>
    public static Quaternion operator *(double factor, Quaternion q) => q * factor;

    /// <summary><c>a</c> times the inverse of <c>b</c>.</summary>
    public static Quaternion operator /(Quaternion a, Quaternion b) => a * Inverse(b);

    /// <summary>Component-wise sum (the original's static name for <c>+</c>).</summary>
    public static Quaternion Addition(Quaternion q1, Quaternion q2) => q1 + q2;

    /// <summary>Component-wise difference (the original's static name for <c>-</c>).</summary>
    public static Quaternion Subtraction(Quaternion q1, Quaternion q2) => q1 - q2;

    /// <summary>Hamilton product (the original's static name for <c>*</c>).</summary>
    public static Quaternion Multiplication(Quaternion q1, Quaternion q2) => q1 * q2;

    /// <summary><c>q1</c> times the inverse of <c>q2</c> (the original's static name for <c>/</c>).</summary>
    public static Quaternion Division(Quaternion q1, Quaternion q2) => q1 / q2;

    /// <summary>A copy with every component times <paramref name="factor"/> (the original returned an unscaled copy: a bug).</summary>
    public static Quaternion Scale(Quaternion q, double factor) => q * factor;

    /// <summary>The conjugate: the vector part negated.</summary>
    public static Quaternion Conjugate(Quaternion q) => new(q.W, -q.X, -q.Y, -q.Z);

    /// <summary>The inverse: the conjugate divided by the squared length (a zero quaternion is returned unchanged, as in the original).</summary>
    public static Quaternion Inverse(Quaternion q)
    {
        double n = q.SqLength();
        return n < 1e-12 ? q : new Quaternion(q.W / n, -q.X / n, -q.Y / n, -q.Z / n);
    }

    /// <summary>Exact component equality.</summary>
    public bool Equals(Quaternion other) => W == other.W && X == other.X && Y == other.Y && Z == other.Z;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is Quaternion q && Equals(q);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(W, X, Y, Z);

    /// <summary>Exact component equality.</summary>
    public static bool operator ==(Quaternion a, Quaternion b) => a.Equals(b);

    /// <summary>Exact component inequality.</summary>
    public static bool operator !=(Quaternion a, Quaternion b) => !a.Equals(b);

    /// <summary>Text <c>[w, x, y, z]</c> with 4 decimals, as in the original.</summary>
    public override string ToString() => $"[{Num.F(W, 4)}, {Num.F(X, 4)}, {Num.F(Y, 4)}, {Num.F(Z, 4)}]";
}
