namespace Machina.Simulation.UrScript;

internal sealed partial class UrTwinController
{
    private UrBlend? _blend;

    /// <summary>The blend the arm may make now (its last motion returned in the zone of its waypoint), or null.</summary>
    public UrBlend? PendingBlend
    {
        get
        {
            lock (_holdGate)
            {
                return _blend;
            }
        }
        internal set
        {
            lock (_holdGate)
            {
                _blend = value;
            }
        }
    }

    /// <summary>Takes the pending blend (null when there is none): the caller either blends from it or finishes it.</summary>
    internal UrBlend? TakeBlend()
    {
        lock (_holdGate)
        {
            UrBlend? blend = _blend;
            _blend = null;
            return blend;
        }
    }

    /// <summary>
    /// Lets the arm finish <paramref name="blend"/>: from the zone's entry it slows down to stop at the waypoint, as a UR does when no
    /// motion follows. The waypoint was traced when the blended motion returned; this part of its way is not traced again.
    /// </summary>
    internal void FinishBlend(UrBlend blend, CancellationToken cancellation)
    {
        SpeedProfile profile = SpeedProfile.Plan(blend.Radius, blend.Speed, blend.Speed > 0 ? blend.Speed : blend.Cruise, 0, blend.Acceleration);
        Joints start = Arm.Joints;
        Joints Along(double f)
        {
            if (f >= 1)
            {
                return blend.CornerJoints;
            }
            Joints near = UrMotion.Lerp(start, blend.CornerJoints, f);
            var pose = new Pose(blend.Entry.Position + (blend.Corner.Position - blend.Entry.Position) * f, UrGeometry.Slerp(blend.Entry.Rotation, blend.Corner.Rotation, f));
            try
            {
                return Arm.Solve(pose, near);
            }
            catch (Twin.TwinMotionException)
            {
                return near;
            }
        }
        double radius = blend.Radius;
        Move(blend.CornerJoints, profile.Seconds, blend.Cruise / blend.Acceleration, t => radius > 0 ? profile.DistanceAt(t) / radius : 1, Along,
            blend.Line, blend.Function + " (to its waypoint)", cancellation, null, false);
    }
}
