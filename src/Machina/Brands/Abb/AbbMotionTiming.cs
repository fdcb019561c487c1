namespace Machina;

/// <summary>
/// How an ABB controller times Machina's RAPID: every motion, <c>MoveAbsJ</c> included, runs its TCP at the speeddata's
/// <c>v_tcp</c> and turns at its <c>v_ori</c> (Machina writes the same number to both), whichever takes longer; ramps at the
/// program's <c>WorldAccLim</c>, else at <see cref="DefaultAcceleration"/>.
/// </summary>
internal sealed class AbbMotionTiming : MotionTiming
{
    /// <summary>The TCP acceleration assumed when the program sets none, mm/s². ABB's real value comes from the arm's dynamic model and its load; this is a typical one for a small arm (the virtual ABB uses the same).</summary>
    internal const double DefaultAcceleration = 5000;

    internal override BlendTiming NewBlendTiming() => new AbbBlendTiming();

    internal override double? Seconds(in TimedMotion motion, RobotModel? model)
    {
        if (motion.Millimetres is not double mm)
        {
            return null;
        }
        double acceleration = motion.ControllerAcceleration ? DefaultAcceleration : motion.Acceleration;
        return Math.Max(Trapezoid(mm, motion.Speed, acceleration), (motion.TurnDegrees ?? 0) / motion.Speed);
    }
}
