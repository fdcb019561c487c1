namespace Machina;

/// <summary>
/// How a UR controller times Machina's URScript (URScript manual, <c>movej</c>/<c>movel</c>): a joint move runs its largest
/// joint travel at <c>v</c> rad/s ramping at <c>a</c> rad/s²; a linear move its path at <c>v</c> m/s with <c>a</c> m/s², or,
/// when the tool only turns, the turn in rad at the same numbers. Without <c>a</c> in the script, the functions' defaults.
/// </summary>
internal sealed class UrMotionTiming : MotionTiming
{
    /// <summary>movej's default joint acceleration, rad/s² (URScript manual).</summary>
    internal const double DefaultJointAcceleration = 1.4;

    /// <summary>movel's default tool acceleration, m/s² (URScript manual).</summary>
    internal const double DefaultToolAcceleration = 1.2;

    private const double DegreesToRadians = Math.PI / 180;

    internal override BlendTiming NewBlendTiming() => new UrBlendTiming();

    internal override double? Seconds(in TimedMotion motion, RobotModel? model)
    {
        if (motion.IsJoint)
        {
            return motion.LargestJointTravel is double degrees
                ? Trapezoid(degrees * DegreesToRadians, motion.Speed * DegreesToRadians,
                    motion.ControllerAcceleration ? DefaultJointAcceleration : motion.Acceleration * DegreesToRadians)
                : null;
        }
        if (motion.Millimetres is not double mm)
        {
            return null;
        }
        double acceleration = motion.ControllerAcceleration ? DefaultToolAcceleration : motion.Acceleration / 1000;
        double distance = mm / 1000 > 1e-6 ? mm / 1000 : (motion.TurnDegrees ?? 0) * DegreesToRadians;
        return Trapezoid(distance, motion.Speed / 1000, acceleration);
    }
}
