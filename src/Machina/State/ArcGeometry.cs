namespace Machina;

/// <summary>Circle arcs through three points: start, through and end.</summary>
internal static class ArcGeometry
{
    /// <summary>Length (mm) of the circular arc from <paramref name="start"/> through <paramref name="through"/> to <paramref name="end"/>; false with a reason when the points do not define an arc.</summary>
    internal static bool TryLength(Vector start, Vector through, Vector end, out double length, out string? problem)
    {
        length = 0;
        problem = null;
        Vector a = through - start, b = end - start;
        Vector normal = Vector.Cross(a, b);
        double n2 = normal.SquaredLength;
        double scale = Math.Max(a.SquaredLength, b.SquaredLength);
        if (!double.IsFinite(n2) || !double.IsFinite(scale * scale))
        {
            problem = "the arc is too large to compute (its points are more than about 1E+77 mm apart).";
            return false;
        }
        if (a.SquaredLength < 1e-12 || b.SquaredLength < 1e-12 || (end - through).SquaredLength < 1e-12 || n2 <= 1e-18 * scale * scale)
        {
            problem = "the start, through and end points of the arc are on one line or coincide, so they do not define a circle.";
            return false;
        }
        // Circumcentre relative to start: ((|a|² b − |b|² a) × (a × b)) / (2 |a × b|²).
        Vector center = Vector.Cross((b * a.SquaredLength) - (a * b.SquaredLength), normal) * (1 / (2 * n2));
        Vector rs = -center, rt = a - center, re = b - center;
        double radius = rs.Length;
        double angleThrough = SignedAngle(rs, rt, normal);
        double angleEnd = SignedAngle(rs, re, normal);
        // The arc goes from start in the direction that meets "through" before "end".
        double sweep = angleThrough <= angleEnd ? angleEnd : angleEnd - 2 * Math.PI;
        length = Math.Abs(sweep) * radius;
        if (!double.IsFinite(length))
        {
            problem = "the arc is too large to compute (its points are more than about 1E+77 mm apart).";
            return false;
        }
        return true;
    }

    private static double SignedAngle(Vector from, Vector to, Vector normal)
    {
        double angle = Math.Atan2(Vector.Dot(Vector.Cross(from, to), normal.Normalized()), Vector.Dot(from, to));
        return angle < 0 ? angle + 2 * Math.PI : angle;
    }
}
