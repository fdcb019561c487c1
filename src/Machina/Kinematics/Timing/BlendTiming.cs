namespace Machina;

/// <summary>
/// A brand's blends in one cycle-time estimate: it follows the program action by action (it has state: one per trial) and gives
/// each motion its time with the blends around it (<see cref="BlendModel"/>). A blended motion is first timed as if it stopped at
/// its waypoint; when the next motion blends with it, that motion's time takes back what the stop would have cost, so that the sum
/// so far is always the time of the program if it ended there.
/// </summary>
internal abstract class BlendTiming
{
    /// <summary>The seconds of the applied <paramref name="action"/> (<paramref name="plain"/>: its time without blends), given the blend radius in force in mm.</summary>
    internal abstract double? Seconds(RobotAction action, in TimedMotion motion, double radiusMm, double? plain);

    /// <summary>Tells that an action that is not a motion was applied: one that makes the controller wait ends a pending blend.</summary>
    internal abstract void NotMotion(RobotAction action);
}
