namespace Machina;

/// <summary>
/// A position in space in millimetres; converts freely to and from <see cref="Vector"/>. Kept for programs written for the original Machina.
/// </summary>
/// <param name="X">X coordinate (mm).</param>
/// <param name="Y">Y coordinate (mm).</param>
/// <param name="Z">Z coordinate (mm).</param>
public readonly record struct Point(double X, double Y, double Z)
{
    /// <summary>The origin (0, 0, 0).</summary>
    public static Point Origin => default;

    /// <summary>Converts a point to a vector from the origin.</summary>
    public static implicit operator Vector(Point p) => new(p.X, p.Y, p.Z);

    /// <summary>Converts a vector to the point it reaches from the origin.</summary>
    public static implicit operator Point(Vector v) => new(v.X, v.Y, v.Z);

    /// <summary>Text such as <c>[400, 300, 500]</c> (3 decimals), as <see cref="Vector.ToString"/> writes a position.</summary>
    public override string ToString() => ((Vector)this).ToString();
}
