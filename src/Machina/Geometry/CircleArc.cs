namespace Machina;

/// <summary>
/// The circle through a start, a through and an end point, as G-code and the reach checks need it: centre, turning direction and swept angle,
/// and points along the way for printers that draw arcs as short straight segments.
/// </summary>
internal readonly struct CircleArc
{
    private readonly Vector _u, _v;
    private readonly double _startAngle;

    private CircleArc(Vector center, Vector u, Vector v, double radius, double startAngle, double sweep)
    {
        Center = center;
        _u = u;
        _v = v;
        Radius = radius;
        _startAngle = startAngle;
        Sweep = sweep;
    }

    /// <summary>Centre of the circle, mm.</summary>
    internal Vector Center { get; }

    /// <summary>Radius, mm.</summary>
    internal double Radius { get; }

    /// <summary>Angle swept from start to end, radians, in (0, 2π), counter-clockwise about <see cref="Normal"/>.</summary>
    internal double Sweep { get; }

    /// <summary>Unit normal of the arc's plane; seen from its tip, the arc turns counter-clockwise.</summary>
    internal Vector Normal => Vector.Cross(_u, _v);

    /// <summary>Length of the arc, mm.</summary>
    internal double Length => Radius * Sweep;

    /// <summary>The circle from <paramref name="start"/> through <paramref name="through"/> to <paramref name="end"/>; false when the points are on one line.</summary>
    internal static bool TryCreate(Vector start, Vector through, Vector end, out CircleArc arc)
    {
        arc = default;
        Vector toThrough = through - start, toEnd = end - start;
        double throughDistance = toThrough.Length;
        if (throughDistance < 1e-9)
        {
            return false;
        }
        // A plane basis with start at the origin and "through" on the u axis; "end" then lies above it (positive v).
        Vector u = toThrough / throughDistance;
        Vector across = toEnd - u * Vector.Dot(toEnd, u);
        double height = across.Length;
        if (height < 1e-9 * Math.Max(1, toEnd.Length))
        {
            return false;
        }
        Vector v = across / height;
        double ex = Vector.Dot(toEnd, u);
        // Circumcentre in the plane: on the bisector x = d/2 of start and through, equidistant from end.
        double cx = throughDistance / 2;
        double cy = (ex * ex + height * height - throughDistance * ex) / (2 * height);
        double startAngle = Math.Atan2(-cy, -cx);
        double sweep = Math.Atan2(height - cy, ex - cx) - startAngle;
        while (sweep <= 0)
        {
            sweep += 2 * Math.PI;
        }
        while (sweep > 2 * Math.PI)
        {
            sweep -= 2 * Math.PI;
        }
        arc = new CircleArc(start + u * cx + v * cy, u, v, Math.Sqrt(cx * cx + cy * cy), startAngle, sweep);
        return true;
    }

    /// <summary>The point reached after turning <paramref name="fraction"/> (0 to 1) of the sweep.</summary>
    internal Vector PointAt(double fraction)
    {
        double angle = _startAngle + Sweep * fraction;
        return Center + _u * (Radius * Math.Cos(angle)) + _v * (Radius * Math.Sin(angle));
    }

    /// <summary>How many straight segments keep every chord within <paramref name="tolerance"/> mm of the arc (at least 1, at most 10 000).</summary>
    internal int SegmentCount(double tolerance)
    {
        if (Radius <= tolerance)
        {
            return Math.Max(1, (int)Math.Ceiling(Sweep / (Math.PI / 2)));
        }
        double maxStep = 2 * Math.Acos(1 - tolerance / Radius);
        return (int)Math.Clamp(Math.Ceiling(Sweep / maxStep), 1, 10_000);
    }
}
