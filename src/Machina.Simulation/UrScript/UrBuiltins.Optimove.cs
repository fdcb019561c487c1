namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>Tool speed (m/s) that <c>optimovel</c>'s v = 1 stands for: the e-Series' typical TCP speed (the twin's assumption).</summary>
    internal const double OptimoveToolSpeed = 1.0;

    /// <summary>Tool acceleration (m/s²) that <c>optimovel</c>'s a = 1 stands for (the twin's assumption: UR publishes none).</summary>
    internal const double OptimoveToolAcceleration = 10.0;

    /// <summary>Joint acceleration (rad/s²) that <c>optimovej</c>'s a = 1 stands for (the twin's assumption: UR publishes none).</summary>
    internal const double OptimoveJointAcceleration = 15.0;

    /// <summary>Joint speed (rad/s) that <c>optimovej</c>'s v = 1 stands for when the model publishes none: 180 °/s.</summary>
    private const double DefaultJointSpeed = Math.PI;

    /// <summary>
    /// OptiMove (software 5.21) and direct torque control (5.23), approximated: the Script Manual's <c>optimovej</c>/<c>optimovel</c>
    /// take a and v as fractions (0, 1] of what the robot can do and move on jerk-limited profiles; the twin checks the fractions,
    /// scales them by the capabilities above (joint speed: the model's slowest joint) and moves as <c>movej</c>/<c>movel</c> do,
    /// on a trapezoid (so a little faster than a jerk-limited profile). <c>direct_torque</c> checks its six torques; the twin has
    /// no dynamics, so no torque moves the arm: it stands.
    /// </summary>
    private static void AddOptimove(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "optimovej", (m, line, a) =>
        {
            (double acc, double v) = Fractions(a, line, "optimovej");
            Joints? speeds = m.Controller.Arm.Model.MaxJointSpeeds;
            double top = speeds is Joints s ? s.ToArray().Min() * Math.PI / 180 : DefaultJointSpeed;
            return MoveJ(m, line, [a[0], acc * OptimoveJointAcceleration, v * top, 0.0, a[3]], "optimovej");
        }, R("q"), O("a", 0.3), O("v", 0.3), O("r", 0));
        Add(t, "optimovel", (m, line, a) =>
        {
            (double acc, double v) = Fractions(a, line, "optimovel");
            return MoveLinear(m, line, [a[0], acc * OptimoveToolAcceleration, v * OptimoveToolSpeed, 0.0, a[3]], "optimovel");
        }, R("goal"), O("a", 0.3), O("v", 0.3), O("r", 0));
        Add(t, "direct_torque", (m, line, a) =>
        {
            Six(a, 0, line, "direct_torque", "torque");
            Bool(a, 1, line, "direct_torque", "friction_comp");
            FinishBlend(m, line);
            return UrNone.Value; // no dynamics: the arm stands
        }, R("torque"), O("friction_comp", true));
    }

    /// <summary>OptiMove's a and v: fractions in (0, 1].</summary>
    private static (double A, double V) Fractions(object[] a, int line, string function)
    {
        double acc = Num(a, 1, line, function, "a"), v = Num(a, 2, line, function, "v");
        foreach ((double value, string name) in new[] { (acc, "a"), (v, "v") })
        {
            if (!(value > 0 && value <= 1))
            {
                throw new UrRuntimeException(line, FormattableString.Invariant($"{function}: argument '{name}' must be a fraction in (0, 1], not {UrValue.FormatNumber(value)}"));
            }
        }
        return (acc, v);
    }
}
