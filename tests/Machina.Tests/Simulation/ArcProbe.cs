namespace Machina.Tests.Simulation;

/// <summary>
/// Where a tool centre point is on a quarter circle: its distance to the centre and its angle from the start, measured in the plane of
/// the start and end radii (the start at 0°, the end at 90°).
/// </summary>
internal sealed class ArcProbe(Vector centre, Vector start, Vector end)
{
    private readonly Vector _x = (start - centre).Normalized();
    private readonly Vector _y = (end - centre).Normalized();

    /// <summary>The distance of <paramref name="point"/> to the centre, in mm.</summary>
    public double Radius(Vector point) => (point - centre).Length;

    /// <summary>The angle of <paramref name="point"/> around the centre from the start, in degrees.</summary>
    public double Angle(Vector point) => Math.Atan2(Vector.Dot(point - centre, _y), Vector.Dot(point - centre, _x)) * 180 / Math.PI;

    /// <summary>How far <paramref name="point"/> is from the plane of the circle, in mm.</summary>
    public double OffPlane(Vector point) => Math.Abs(Vector.Dot(point - centre, Vector.Cross(_x, _y)));

    /// <summary>Asserts that <paramref name="point"/> is on the circle (radius 100 ± 0.1 mm, in its plane) at <paramref name="degrees"/> ± 0.5°.</summary>
    public void AssertAt(Vector point, double degrees, string what)
    {
        Assert.True(Math.Abs(Radius(point) - 100) <= 0.1, FormattableString.Invariant($"{what}: {Radius(point):0.###} mm from the centre, not 100 ({point})"));
        Assert.True(OffPlane(point) <= 0.1, FormattableString.Invariant($"{what}: {OffPlane(point):0.###} mm off the circle's plane ({point})"));
        Assert.True(Math.Abs(Angle(point) - degrees) <= 0.5, FormattableString.Invariant($"{what}: at {Angle(point):0.###}°, expected {degrees:0.###}° ({point})"));
    }
}
