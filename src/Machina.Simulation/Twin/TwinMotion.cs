namespace Machina.Simulation.Twin;

/// <summary>Motion timing: how long a move takes with a trapezoidal speed profile.</summary>
internal static class TwinMotion
{
    /// <summary>
    /// Seconds to travel <paramref name="distance"/> starting and ending at rest, accelerating at <paramref name="acceleration"/> up to
    /// <paramref name="speed"/> (same units: m, m/s, m/s² or rad, rad/s, rad/s²). A short move that never reaches full speed is a triangle.
    /// </summary>
    public static double TrapezoidSeconds(double distance, double speed, double acceleration)
    {
        if (distance <= 0)
        {
            return 0;
        }
        double rampDistance = speed * speed / acceleration;
        return distance >= rampDistance ? distance / speed + speed / acceleration : 2 * Math.Sqrt(distance / acceleration);
    }
}
