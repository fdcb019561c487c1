using System.Runtime.CompilerServices;
namespace Machina;

/// <summary>
/// A direction or position in space, in millimetres. Every value is valid; <c>default</c> is the zero vector.
/// </summary>
/// <param name="X">X component (mm).</param>
/// <param name="Y">Y component (mm).</param>
/// <param name="Z">Z component (mm).</param>
public readonly record struct Vector(double X, double Y, double Z)
{
    /// <summary>The zero vector (0, 0, 0).</summary>
    public static Vector Zero => default;

    /// <summary>The world X axis (1, 0, 0).</summary>
    public static Vector XAxis => new(1, 0, 0);

    /// <summary>The world Y axis (0, 1, 0).</summary>
    public static Vector YAxis => new(0, 1, 0);

    /// <summary>The world Z axis (0, 0, 1).</summary>
    public static Vector ZAxis => new(0, 0, 1);

    /// <summary>Length of the vector.</summary>
    public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);

    /// <summary>Squared length of the vector (cheaper than <see cref="Length"/>).</summary>
    public double SquaredLength => X * X + Y * Y + Z * Z;

    /// <summary>True when every component is a finite number.</summary>
    public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y) && double.IsFinite(Z);

    /// <summary>True when the length is below 1e-6.</summary>
    public bool IsZero => SquaredLength < 1e-12;

    /// <summary>A vector of length 1 in the same direction. Throws when the vector is (almost) zero.</summary>
    public Vector Normalized()
    {
        double length = Length;
        if (double.IsPositiveInfinity(length) && IsFinite)
        {
            // Finite but huge components overflow the squared length: scale down first.
            return (this / Math.Max(Math.Abs(X), Math.Max(Math.Abs(Y), Math.Abs(Z)))).Normalized();
        }
        if (!(length >= 1e-9) || !double.IsFinite(length))
        {
            throw new ArgumentException($"Cannot normalise the vector {this}: it has no direction (length {Num.G(length)}).");
        }
        return new Vector(X / length, Y / length, Z / length);
    }

    /// <summary>Dot product.</summary>
    public static double Dot(Vector a, Vector b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    /// <summary>Right-handed cross product a × b.</summary>
    public static Vector Cross(Vector a, Vector b) =>
        new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

    /// <summary>Distance between two points.</summary>
    public static double Distance(Vector a, Vector b) => (a - b).Length;

    /// <summary>Squared length (the original's method form of <see cref="SquaredLength"/>).</summary>
    public double SqLength() => SquaredLength;

    /// <summary>True when the length is 1 (within 1e-6 on the squared length), as in the original.</summary>
    public bool IsUnit() => Math.Abs(SquaredLength - 1) < 1e-6;

    /// <summary>Distance from this point to <paramref name="other"/>.</summary>
    public double DistanceTo(Vector other) => Distance(this, other);

    /// <summary>Squared distance between two points (cheaper than <see cref="Distance"/>).</summary>
    public static double SqDistance(Vector a, Vector b) => (a - b).SquaredLength;

    /// <summary>Dot product (the original's name for <see cref="Dot"/>).</summary>
    public static double DotProduct(Vector a, Vector b) => Dot(a, b);

    /// <summary>Cross product, right-handed (the original's name for <see cref="Cross"/>).</summary>
    public static Vector CrossProduct(Vector a, Vector b) => Cross(a, b);

    /// <summary>Angle between two vectors in radians (0 when either is zero), as in the original; <see cref="AngleBetweenDegrees"/> gives degrees.</summary>
    public static double AngleBetween(Vector a, Vector b) => AngleBetweenDegrees(a, b) * Angles.ToRadians;

    /// <summary>True when the vectors point the same way (within 1e-6 rad; a zero vector counts as parallel), as in the original.</summary>
    public static bool AreParallel(Vector vec1, Vector vec2) => AngleBetween(vec1, vec2) < 1e-6;

    /// <summary>True when the vectors are perpendicular (within 1e-6 rad), as in the original.</summary>
    public static bool AreOrthogonal(Vector vec1, Vector vec2) => Math.Abs(AngleBetween(vec1, vec2) - Math.PI / 2) < 1e-6;

    /// <summary>True when the vectors point opposite ways (within 1e-6 rad), as in the original.</summary>
    public static bool AreOpposite(Vector vec1, Vector vec2) => Math.Abs(AngleBetween(vec1, vec2) - Math.PI) < 1e-6;

    /// <summary>Angle between two vectors in degrees (0 when either is zero).</summary>
    public static double AngleBetweenDegrees(Vector a, Vector b)
    {
        double la = a.Length, lb = b.Length;
        if (la < 1e-12 || lb < 1e-12)
        {
            return 0;
        }
        // atan2 of |a × b| and a · b keeps tiny and near-180° angles exact (acos of the cosine loses them); scaling
        // each vector by its largest component first keeps huge components from overflowing.
        a = a.ScaledToUnitMax();
        b = b.ScaledToUnitMax();
        return Math.Atan2(Cross(a, b).Length, Dot(a, b)) * Angles.ToDegrees;
    }

    private Vector ScaledToUnitMax() => this / Math.Max(Math.Abs(X), Math.Max(Math.Abs(Y), Math.Abs(Z)));

    /// <summary>Sum of two vectors.</summary>
    public static Vector operator +(Vector a, Vector b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    /// <summary>Difference of two vectors.</summary>
    public static Vector operator -(Vector a, Vector b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    /// <summary>Opposite vector.</summary>
    public static Vector operator -(Vector a) => new(-a.X, -a.Y, -a.Z);

    /// <summary>Vector scaled by a number.</summary>
    public static Vector operator *(Vector a, double s) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Vector scaled by a number.</summary>
    public static Vector operator *(double s, Vector a) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Vector divided by a number.</summary>
    public static Vector operator /(Vector a, double s) => new(a.X / s, a.Y / s, a.Z / s);

    /// <summary>True when every component differs by less than <paramref name="tolerance"/>.</summary>
    public bool IsSimilar(Vector other, double tolerance = 1e-6) =>
        Math.Abs(X - other.X) < tolerance && Math.Abs(Y - other.Y) < tolerance && Math.Abs(Z - other.Z) < tolerance;

    /// <summary>Text such as <c>[400, 300, 500]</c> (3 decimals).</summary>
    public override string ToString()
    {
        Span<char> buffer = stackalloc char[MaxTextChars];
        return new string(buffer[..WriteText(buffer, ", ")]);
    }

    /// <summary>Compact text such as <c>[400,300,500]</c> (3 decimals, no spaces).</summary>
    public string ToArrayString()
    {
        Span<char> buffer = stackalloc char[MaxTextChars];
        return new string(buffer[..WriteText(buffer, ",")]);
    }

    /// <summary>Characters enough for <see cref="WriteText"/> with a separator of up to two characters.</summary>
    internal const int MaxTextChars = 3 * NumAppend.MaxChars + 8;

    /// <summary>Writes <c>[x{separator}y{separator}z]</c> (3 decimals) into <paramref name="destination"/> and returns its length.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal int WriteText(Span<char> destination, ReadOnlySpan<char> separator)
    {
        int at = 0;
        destination[at++] = '[';
        at += NumAppend.WriteF(destination[at..], X, 3);
        separator.CopyTo(destination[at..]);
        at += separator.Length;
        at += NumAppend.WriteF(destination[at..], Y, 3);
        separator.CopyTo(destination[at..]);
        at += separator.Length;
        at += NumAppend.WriteF(destination[at..], Z, 3);
        destination[at++] = ']';
        return at;
    }

    internal Vector RequireFinite(string name)
    {
        if (!IsFinite)
        {
            throw new ArgumentException($"{name} must contain finite numbers, but it was ({Num.R(X)}, {Num.R(Y)}, {Num.R(Z)}).", name);
        }
        return this;
    }
}
