namespace Machina.Simulation.Twin;

/// <summary>
/// The path of a circular motion (ABB MoveC, UR movec, KUKA CIRC): the tool centre point on the circle through the start, the via
/// point and the end (arc length fraction f from the start), and the tool turning as <see cref="TwinArcOrientation"/> says (the via
/// point's orientation is not used). Poses are in the robot's base frame, in mm.
/// </summary>
internal sealed class TwinArc
{
    /// <summary>Points of an arc closer than this (mm) do not define a circle: the twin refuses them.</summary>
    public const double MinPointDistanceMm = 0.1;

    /// <summary>Why three points make no arc, as each language's refusal ends: "(two are closer than 0.1 mm, or all three are on one line)".</summary>
    public static readonly string NotACircle = FormattableString.Invariant($"(two are closer than {MinPointDistanceMm} mm, or all three are on one line)");

    private readonly Vector _x, _y, _normal; // the circle's plane: x towards the start, y a quarter turn on, the normal they turn about
    private readonly double _sweep; // radians, in (0, 2π)
    private readonly TwinArcOrientation _orientation;
    private readonly Rotation _endToPath; // path-relative: the end orientation relative to the path, as it was at the start

    private TwinArc(Vector centre, double radius, Vector normal, double sweep, Pose start, Pose end, TwinArcOrientation orientation)
    {
        Centre = centre;
        Radius = radius;
        _normal = normal;
        _x = (start.Position - centre) / radius;
        _y = Vector.Cross(normal, _x);
        _sweep = sweep;
        _orientation = orientation;
        Start = start;
        End = orientation == TwinArcOrientation.FixedToPath ? new Pose(end.Position, WithPath(1, start.Rotation)) : end;
        _endToPath = Rotation.FromAxisAngle(normal, -SweepDegrees) * End.Rotation;
    }

    /// <summary>The tool centre point where the arc starts.</summary>
    public Pose Start { get; }

    /// <summary>The tool centre point where the arc ends (fixed to the path: the end position with the start orientation turned with the circle).</summary>
    public Pose End { get; }

    /// <summary>The centre of the circle (mm).</summary>
    public Vector Centre { get; }

    /// <summary>The radius of the circle (mm).</summary>
    public double Radius { get; }

    /// <summary>The angle the arc sweeps from start to end, in degrees.</summary>
    public double SweepDegrees => _sweep * 180 / Math.PI;

    /// <summary>The length of the arc (mm).</summary>
    public double LengthMm => Radius * _sweep;

    /// <summary>
    /// The arc from <paramref name="start"/> through <paramref name="via"/> to <paramref name="end"/>; null when the three points do not
    /// define a circle (two of them closer than <see cref="MinPointDistanceMm"/>, or all three on one line). The tool turns as
    /// <paramref name="orientation"/> says.
    /// </summary>
    public static TwinArc? Through(Pose start, Vector via, Pose end, TwinArcOrientation orientation)
    {
        Vector a = start.Position, b = end.Position;
        if (Vector.Distance(a, via) < MinPointDistanceMm || Vector.Distance(via, b) < MinPointDistanceMm || Vector.Distance(a, b) < MinPointDistanceMm)
        {
            return null;
        }
        Vector u = via - a, w = b - a;
        Vector normal = Vector.Cross(u, w);
        if (normal.Length < 1e-9 * u.Length * w.Length)
        {
            return null; // on one line
        }
        // The circumcentre of the triangle; seen from the tip of the normal, start, via and end come in counter-clockwise order.
        Vector centre = a + (Vector.Cross(normal, u) * w.SquaredLength + Vector.Cross(w, normal) * u.SquaredLength) / (2 * normal.SquaredLength);
        double radius = Vector.Distance(a, centre);
        Vector n = normal.Normalized(), x = (a - centre) / radius, y = Vector.Cross(n, x);
        double sweep = Math.Atan2(Vector.Dot(b - centre, y), Vector.Dot(b - centre, x));
        return new TwinArc(centre, radius, n, sweep > 0 ? sweep : sweep + 2 * Math.PI, start, end, orientation);
    }

    /// <summary>The tool centre point after <paramref name="fraction"/> (0 to 1) of the arc's length.</summary>
    public Pose At(double fraction)
    {
        if (fraction <= 0)
        {
            return Start;
        }
        if (fraction >= 1)
        {
            return End;
        }
        Rotation rotation = _orientation switch
        {
            TwinArcOrientation.FixedToPath => WithPath(fraction, Start.Rotation),
            TwinArcOrientation.PathRelative => WithPath(fraction, KinematicChecks.Slerp(Start.Rotation, _endToPath, fraction)),
            _ => KinematicChecks.Slerp(Start.Rotation, End.Rotation, fraction),
        };
        double angle = _sweep * fraction;
        return new Pose(Centre + _x * (Radius * Math.Cos(angle)) + _y * (Radius * Math.Sin(angle)), rotation);
    }

    /// <summary>An orientation relative to the path at the start (<paramref name="relative"/>) carried along <paramref name="fraction"/> of the sweep.</summary>
    private Rotation WithPath(double fraction, Rotation relative) => Rotation.FromAxisAngle(_normal, SweepDegrees * fraction) * relative;
}
