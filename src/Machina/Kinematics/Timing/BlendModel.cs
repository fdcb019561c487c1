namespace Machina;

/// <summary>
/// How Machina models a blend between two linear motions (UR's blend radius; UR manual: the arm starts to blend when it is within
/// the radius of the waypoint and does not stop there). The cycle-time estimate and the twins share it, so that they agree:
/// <list type="bullet">
/// <item>a radius is at most half of each of the two motions it joins (blends do not overlap);</item>
/// <item>the first motion ends where the arm enters the zone (the radius before the waypoint), at its cruise speed, or lower when it
/// could not reach it or could not stop at the waypoint from it (the arm can always still stop there if no motion follows);</item>
/// <item>the arm crosses the zone on a parabola from that point, past the waypoint, to the radius along the next motion, at that
/// speed; the next motion goes on from there;</item>
/// <item>when no motion follows (the program ends or waits first), the arm slows down to stop at the waypoint.</item>
/// </list>
/// </summary>
internal static class BlendModel
{
    /// <summary>How many straight pieces stand for the blend's parabola when it is measured.</summary>
    private const int Pieces = 16;

    /// <summary>Below this length (in m) a motion has no straight part to blend with: it only turns the tool.</summary>
    internal const double MinLength = 1e-6;

    /// <summary>
    /// True when turning the tool takes longer than travelling <paramref name="metres"/> in a trapezoid at <paramref name="speed"/>
    /// and <paramref name="acceleration"/> (<paramref name="plainSeconds"/>, the motion's time alone, is longer): such a motion
    /// does not blend on ABB (v_ori) and KUKA ($VEL.ORI1), whose path planners then stop at the corner.
    /// </summary>
    internal static bool TurnDominates(double plainSeconds, double metres, double speed, double acceleration) =>
        plainSeconds > SpeedProfile.Plan(metres, 0, speed, 0, acceleration).Seconds * (1 + 1e-6) + 1e-9;

    /// <summary>The radius a blend at the end of a motion <paramref name="length"/> long can have: at most half of it.</summary>
    internal static double Radius(double radius, double length) => length < MinLength || !(radius > 0) ? 0 : Math.Min(radius, length / 2);

    /// <summary>
    /// The speed at which a motion enters its blend zone of <paramref name="radius"/> after <paramref name="distance"/> of straight
    /// path from <paramref name="startSpeed"/>: its <paramref name="cruise"/> speed, or less when the way is too short to reach it
    /// or when it could not stop within the radius at <paramref name="acceleration"/>.
    /// </summary>
    internal static double EntrySpeed(double distance, double startSpeed, double cruise, double acceleration, double radius)
    {
        if (!(acceleration > 0) || double.IsPositiveInfinity(acceleration))
        {
            return cruise;
        }
        return Math.Min(cruise, Math.Min(Math.Sqrt(startSpeed * startSpeed + 2 * acceleration * Math.Max(0, distance)), Math.Sqrt(2 * acceleration * radius)));
    }

    /// <summary>The point at <paramref name="s"/> (0 to 1) of the blend from <paramref name="entry"/> past <paramref name="corner"/> to <paramref name="exit"/>.</summary>
    internal static Vector Point(Vector entry, Vector corner, Vector exit, double s)
    {
        double u = 1 - s;
        return entry * (u * u) + corner * (2 * s * u) + exit * (s * s);
    }

    /// <summary>The length of the blend's path from <paramref name="entry"/> past <paramref name="corner"/> to <paramref name="exit"/>.</summary>
    internal static double Length(Vector entry, Vector corner, Vector exit)
    {
        double length = 0;
        Vector last = entry;
        for (int i = 1; i <= Pieces; i++)
        {
            Vector next = Point(entry, corner, exit, (double)i / Pieces);
            length += (next - last).Length;
            last = next;
        }
        return length;
    }

    /// <summary>
    /// The point <paramref name="distance"/> along the blend's path from <paramref name="entry"/> past <paramref name="corner"/> to
    /// <paramref name="exit"/> (measured on the same pieces as <see cref="Length"/>, so that the arm keeps an even speed through it).
    /// </summary>
    internal static Vector PointAtDistance(Vector entry, Vector corner, Vector exit, double distance)
    {
        Vector last = entry;
        for (int i = 1; i <= Pieces; i++)
        {
            Vector next = Point(entry, corner, exit, (double)i / Pieces);
            double piece = (next - last).Length;
            if (distance <= piece || i == Pieces)
            {
                return piece > 0 ? last + (next - last) * Math.Clamp(distance / piece, 0, 1) : next;
            }
            distance -= piece;
            last = next;
        }
        return exit;
    }

    /// <summary>Seconds to slow from <paramref name="speed"/> to a stop over <paramref name="radius"/> at <paramref name="acceleration"/> (the end of a blended motion that nothing follows).</summary>
    internal static double StopSeconds(double radius, double speed, double acceleration) =>
        SpeedProfile.Plan(radius, speed, Math.Max(speed, 1e-12), 0, acceleration).Seconds;
}
