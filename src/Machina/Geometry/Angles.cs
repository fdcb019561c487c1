namespace Machina;

/// <summary>Conversion factors between degrees and radians.</summary>
public static class Angles
{
    /// <summary>Multiply radians by this to get degrees.</summary>
    public const double ToDegrees = 180.0 / Math.PI;

    /// <summary>Multiply degrees by this to get radians.</summary>
    public const double ToRadians = Math.PI / 180.0;

    /// <summary>Wraps an angle in degrees into (−180, 180].</summary>
    public static double Wrap180(double degrees)
    {
        double a = Math.IEEERemainder(degrees, 360.0);
        if (a <= -180.0)
        {
            a += 360.0;
        }
        return a;
    }
}
