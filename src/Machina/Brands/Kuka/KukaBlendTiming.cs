namespace Machina;

/// <summary>
/// KUKA approximate positioning in a cycle-time estimate, as the virtual KUKA runs it (<see cref="PathBlendTiming"/>): a <c>LIN</c>
/// with <c>C_DIS</c> ($APO.CDIS, the cursor's precision in mm) rounds the corner into the next <c>LIN</c>; without it the motion stops
/// exactly. A motion whose turn at $VEL.ORI1 takes longer than its path does not approximate.
/// </summary>
internal sealed class KukaBlendTiming : PathBlendTiming
{
    protected override double Acceleration(in TimedMotion motion) =>
        (motion.ControllerAcceleration ? KukaMotionTiming.DefaultPathAcceleration : motion.Acceleration) / 1000;

    protected override bool TurnDominates(in TimedMotion motion, double plain, double metres, double speed, double acceleration) =>
        BlendModel.TurnDominates(plain, metres, speed, acceleration);
}
