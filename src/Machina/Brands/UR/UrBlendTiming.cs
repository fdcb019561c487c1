namespace Machina;

/// <summary>
/// UR blends in a cycle-time estimate, as the virtual UR runs them (<see cref="PathBlendTiming"/>): <c>movel</c> and <c>movep</c>
/// with a blend radius blend into the next linear motion, ramping at <c>a</c> (movel's default when the script gives none).
/// </summary>
internal sealed class UrBlendTiming : PathBlendTiming
{
    protected override double Acceleration(in TimedMotion motion) =>
        motion.ControllerAcceleration ? UrMotionTiming.DefaultToolAcceleration : motion.Acceleration / 1000;
}
