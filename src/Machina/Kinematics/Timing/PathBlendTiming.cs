namespace Machina;

/// <summary>
/// Blends between linear motions in a cycle-time estimate, as the twins run them (<see cref="BlendModel"/>): a linear motion with a
/// radius (UR's blend radius, ABB's zone, KUKA's approximation distance) blends into the next linear motion; a joint motion, an arc,
/// a tool change, a wait or a wait for an input first lets the arm stop at the waypoint. Each brand gives the tool acceleration it
/// ramps at and whether its controller times a motion by its turn. Metres and seconds.
/// </summary>
internal abstract class PathBlendTiming : BlendTiming
{
    private Pending? _pending;

    /// <summary>The tool acceleration of <paramref name="motion"/> on this controller, m/s².</summary>
    protected abstract double Acceleration(in TimedMotion motion);

    /// <summary>True when this controller times <paramref name="motion"/> by its turn (<paramref name="plain"/> is longer than its straight way): then it does not blend.</summary>
    protected virtual bool TurnDominates(in TimedMotion motion, double plain, double metres, double speed, double acceleration) => false;

    internal sealed override double? Seconds(RobotAction action, in TimedMotion motion, double radiusMm, double? plain)
    {
        if (motion.IsJoint || action is ActionArcMotion || plain is not double plainSeconds || motion.FromPosition is not Vector from || motion.ToPosition is not Vector to)
        {
            _pending = null;
            return plain;
        }
        double length = Vector.Distance(from, to) / 1000;
        double speed = motion.Speed / 1000;
        double acceleration = Acceleration(motion);
        if (length < BlendModel.MinLength || TurnDominates(motion, plainSeconds, length, speed, acceleration))
        {
            _pending = null; // the tool only turns (or turns slower than it travels): the arm stops at the last waypoint first, and this one does not blend
            return plain;
        }
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
        if (!(entrySpeed > 0))
        {
            radius = 0;
            straight = length - exitLeg;
        }
        seconds += SpeedProfile.Plan(straight, startSpeed, speed, entrySpeed, acceleration).Seconds;
        _pending = null;
        if (radius > 0)
        {
            double stop = BlendModel.StopSeconds(radius, entrySpeed, acceleration);
            seconds += stop;
            _pending = new Pending(target - direction * radius, radius, entrySpeed, stop);
        }
        return seconds;
    }

    internal sealed override void NotMotion(RobotAction action)
    {
        if (action is ActionWait or ActionWaitDigital or ActionAttachTool or ActionDetachTool)
        {
            _pending = null;
        }
    }

    /// <summary>The blend the last motion may make: where its zone begins (m), its radius, its speed there and what stopping would take.</summary>
    private readonly record struct Pending(Vector Entry, double Radius, double Speed, double StopSeconds);
}
