namespace Machina;

/// <summary>
/// UR blends in a cycle-time estimate, as the virtual UR runs them (<see cref="BlendModel"/>): linear motions (<c>movel</c>,
/// <c>movep</c>) with a blend radius blend into the next linear motion; a joint motion, an arc, a tool change, a wait or a wait for
/// an input first lets the arm stop at the waypoint. Metres and seconds, as the controller counts.
/// </summary>
internal sealed class UrBlendTiming : BlendTiming
{
    private Pending? _pending;

    internal override double? Seconds(RobotAction action, in TimedMotion motion, double radiusMm, double? plain)
    {
        if (motion.IsJoint || action is ActionArcMotion || plain is null || motion.FromPosition is not Vector from || motion.ToPosition is not Vector to)
        {
            _pending = null;
            return plain;
        }
        double length = Vector.Distance(from, to) / 1000;
        if (length < BlendModel.MinLength)
        {
            _pending = null; // only the tool turns: the arm stops at the last waypoint first, and this one does not blend
            return plain;
        }
        double speed = motion.Speed / 1000;
        double acceleration = motion.ControllerAcceleration ? UrMotionTiming.DefaultToolAcceleration : motion.Acceleration / 1000;
        Vector corner = from / 1000, target = to / 1000, direction = (target - corner) / length;
        double seconds = 0, startSpeed = 0, exitLeg = 0;
        if (_pending is { } p)
        {
            exitLeg = Math.Min(p.Radius, length / 2);
            double blend = BlendModel.Length(p.Entry, corner, corner + direction * exitLeg);
            seconds += blend / p.Speed - p.StopSeconds;
            startSpeed = p.Speed;
        }
        double radius = BlendModel.Radius(radiusMm / 1000, length);
        double straight = length - exitLeg - radius;
        double entrySpeed = radius > 0 ? BlendModel.EntrySpeed(straight, startSpeed, speed, acceleration, radius) : 0;
        seconds += SpeedProfile.Plan(straight, startSpeed, speed, entrySpeed, acceleration).Seconds;
        _pending = null;
        if (radius > 0 && entrySpeed > 0)
        {
            double stop = BlendModel.StopSeconds(radius, entrySpeed, acceleration);
            seconds += stop;
            _pending = new Pending(target - direction * radius, radius, entrySpeed, stop);
        }
        return seconds;
    }

    internal override void NotMotion(RobotAction action)
    {
        if (action is ActionWait or ActionWaitDigital or ActionAttachTool or ActionDetachTool)
        {
            _pending = null;
        }
    }

    /// <summary>The blend the last motion may make: where its zone begins (m), its radius, its speed there and what stopping would take.</summary>
    private readonly record struct Pending(Vector Entry, double Radius, double Speed, double StopSeconds);
}
