namespace Machina;

/// <summary>
/// How a KUKA controller times Machina's KRL: <c>LIN</c> and <c>CIRC</c> run the path at <c>$VEL.CP</c> with <c>$ACC.CP</c>, or the
/// turn at <c>$VEL.ORI1</c> with <c>$ACC.ORI1</c> when that is slower; <c>PTP</c> runs each axis at <c>$VEL_AXIS</c> (100 % after
/// <c>BAS(#INITMOV)</c>) of its rated speed and the slowest axis sets the time.
/// </summary>
internal sealed class KukaMotionTiming : MotionTiming
{
    /// <summary>$ACC.CP after BAS(#INITMOV) when the program sets none, mm/s² (the virtual KUKA uses the same).</summary>
    internal const double DefaultPathAcceleration = 2300;

    /// <summary>$VEL.ORI1 and $ACC.ORI1 as the program leaves them: deg/s and deg/s².</summary>
    internal const double TurnSpeed = 400, TurnAcceleration = 1000;

    /// <summary>An axis' rated speed when the arm model has none, deg/s, and the time an axis takes to reach it, s.</summary>
    internal const double FallbackAxisSpeed = 180, AxisRampSeconds = 0.3;

    internal override BlendTiming NewBlendTiming() => new KukaBlendTiming();

    internal override double? Seconds(in TimedMotion motion, RobotModel? model)
    {
        if (motion.IsJoint)
        {
            if (motion.FromJoints is not Joints from || motion.ToJoints is not Joints to)
            {
                return null;
            }
            double slowest = 0;
            for (int i = 0; i < 6; i++)
            {
                double rated = model?.MaxJointSpeeds is Joints max ? max[i] : FallbackAxisSpeed;
                slowest = Math.Max(slowest, Trapezoid(Math.Abs(to[i] - from[i]), rated, rated / AxisRampSeconds));
            }
            return slowest;
        }
        if (motion.Millimetres is not double mm)
        {
            return null;
        }
        double acceleration = motion.ControllerAcceleration ? DefaultPathAcceleration : motion.Acceleration;
        return Math.Max(Trapezoid(mm, motion.Speed, acceleration), Trapezoid(motion.TurnDegrees ?? 0, TurnSpeed, TurnAcceleration));
    }
}
