namespace Machina;

/// <summary>
/// How a brand's controller turns a motion and the program's speed settings into seconds (docs/cycle-time.md). Each arm brand
/// declares its own in its folder (<see cref="BrandDefinition.Timing"/>); the others use <see cref="Generic"/>. A brand that
/// models its blends gives a <see cref="BlendTiming"/> per estimate; the others time a blended path as its exact one.
/// </summary>
internal abstract class MotionTiming
{
    /// <summary>Path speed over path length, turns at the same speed in deg/s, ramps at the program's acceleration when it sets one.</summary>
    internal static MotionTiming Generic { get; } = new GenericMotionTiming();

    /// <summary>Seconds <paramref name="motion"/> takes on the arm <paramref name="model"/> (or an unknown arm), or null when the motion lacks what this controller times it by (a pose or joints not known).</summary>
    internal abstract double? Seconds(in TimedMotion motion, RobotModel? model);

    /// <summary>A new follower of blends for one estimate, or null when this controller's blends are not modelled (then not shortened).</summary>
    internal virtual BlendTiming? NewBlendTiming() => null;

    /// <summary>
    /// Seconds to travel <paramref name="distance"/> from rest to rest, accelerating at <paramref name="acceleration"/> up to
    /// <paramref name="speed"/> (any one unit of length or angle); a move too short to reach full speed is a triangle.
    /// </summary>
    internal static double Trapezoid(double distance, double speed, double acceleration)
    {
        if (distance <= 0 || !(speed > 0))
        {
            return 0;
        }
        if (!(acceleration > 0) || double.IsPositiveInfinity(acceleration))
        {
            return distance / speed;
        }
        double rampDistance = speed * speed / acceleration;
        return distance >= rampDistance ? distance / speed + speed / acceleration : 2 * Math.Sqrt(distance / acceleration);
    }

    private sealed class GenericMotionTiming : MotionTiming
    {
        internal override double? Seconds(in TimedMotion motion, RobotModel? model)
        {
            double acceleration = motion.ControllerAcceleration ? 0 : motion.Acceleration;
            if (motion.IsJoint && model?.MaxJointSpeeds is Joints max && motion.FromJoints is Joints from && motion.ToJoints is Joints to)
            {
                double slowest = 0;
                for (int i = 0; i < 6; i++)
                {
                    slowest = Math.Max(slowest, Math.Abs(to[i] - from[i]) / max[i]);
                }
                return slowest;
            }
            if (motion.Millimetres is not double mm)
            {
                return null;
            }
            return Math.Max(Trapezoid(mm, motion.Speed, acceleration), (motion.TurnDegrees ?? 0) / motion.Speed);
        }
    }
}
