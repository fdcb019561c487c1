namespace Machina;

/// <summary>
/// Robot controllers turn the tool evenly from the start to the end orientation of an arc and use only the position of
/// the through point (ABB MoveC in its default path mode, UR movec). This tells when an arc asked for something else.
/// </summary>
internal static class ArcOrientation
{
    /// <summary>Largest accepted difference, degrees, between the requested through orientation and the even turn's midpoint.</summary>
    internal const double ToleranceDegrees = 0.1;

    /// <summary>True when the arc just applied to <paramref name="cursor"/> asked for a through orientation off the even turn.</summary>
    internal static bool ThroughIsIgnored(ActionArcMotion arc, RobotCursor cursor)
    {
        if (arc.PositionOnly || cursor.PrevRotation is not Rotation start || cursor.Rotation is not Rotation end
            || cursor.ArcThroughRotation is not Rotation through)
        {
            return false;
        }
        double sign = start.W * end.W + start.X * end.X + start.Y * end.Y + start.Z * end.Z < 0 ? -1 : 1;
        Rotation midpoint = Rotation.FromQuaternion(start.W + sign * end.W, start.X + sign * end.X, start.Y + sign * end.Y, start.Z + sign * end.Z);
        return !through.IsSimilar(midpoint, ToleranceDegrees);
    }
}
