namespace Machina;

/// <summary>
/// ABB zones in a cycle-time estimate, as the virtual ABB runs them (<see cref="PathBlendTiming"/>): a <c>MoveL</c> with a zone
/// (pzone_tcp, the cursor's precision in mm) rounds the corner into the next <c>MoveL</c>; <c>fine</c> stops. A move whose turn
/// at v_ori takes longer than its path does not blend.
/// </summary>
internal sealed class AbbBlendTiming : PathBlendTiming
{
    protected override double Acceleration(in TimedMotion motion) =>
        (motion.ControllerAcceleration ? AbbMotionTiming.DefaultAcceleration : motion.Acceleration) / 1000;

    protected override bool TurnDominates(in TimedMotion motion, double plain, double metres, double speed, double acceleration) =>
        BlendModel.TurnDominates(plain, metres, speed, acceleration);
}
