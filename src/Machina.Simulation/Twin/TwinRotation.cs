namespace Machina.Simulation.Twin;

/// <summary>Rotation arithmetic every twin needs, whatever its language.</summary>
internal static class TwinRotation
{
    /// <summary>The angle of the smallest rotation from <paramref name="a"/> to <paramref name="b"/>, in radians.</summary>
    public static double AngleBetween(Rotation a, Rotation b)
    {
        double dot = Math.Abs(a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z);
        return 2 * Math.Acos(Math.Min(1, dot));
    }

    /// <summary>The angle of the smallest rotation from <paramref name="a"/> to <paramref name="b"/>, in degrees.</summary>
    public static double AngleDegrees(Rotation a, Rotation b) => AngleBetween(a, b) * 180 / Math.PI;
}
