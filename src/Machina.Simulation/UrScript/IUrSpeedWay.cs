namespace Machina.Simulation.UrScript;

/// <summary>
/// The way of a speed motion (<c>speedj</c>: <see cref="UrSpeedPath"/>, <c>speedl</c>: <see cref="UrToolSpeedPath"/>): the joints
/// some seconds after its start, and where it must end (a joint at its limit, the tool out of reach). A way may be known only
/// part of the way ahead (<see cref="KnownUntil"/>): <see cref="Extend"/> looks further, so a long motion costs nothing up front.
/// </summary>
internal interface IUrSpeedWay
{
    /// <summary>Seconds after the start when the way must end (infinite: not within what is known of it).</summary>
    double LimitSeconds { get; }

    /// <summary>Why the way ends at <see cref="LimitSeconds"/>: the protective stop's reason (e.g. "joint 6 position limit violated").</summary>
    string LimitReason { get; }

    /// <summary>How far ahead (seconds after the start) the way and its limit are known: infinite when to its end.</summary>
    double KnownUntil { get; }

    /// <summary>Looks ahead to <paramref name="seconds"/> after the start (or to the limit, if it comes first).</summary>
    void Extend(double seconds);

    /// <summary>The joints <paramref name="seconds"/> after the start (where the way ends, past its limit).</summary>
    Joints At(double seconds);

    /// <summary>This way as a motion's path that lasts <paramref name="duration"/> seconds, at its own speeds.</summary>
    IUrMotionPath Over(double duration);
}
