namespace Machina.Simulation.Rapid;

/// <summary>
/// What MoveC asks of its three points (RAPID reference manual, MoveC, "Limitations"): the CirPoint and the ToPoint each at
/// least 0.1 mm from the start point (<see cref="Twin.TwinArc"/> refuses closer points) and at least 1° apart seen from the start
/// point. Points closer to one line than that define a circle the controller cannot trust (a huge radius from points a few
/// tenths of a millimetre off a line): it stops the program with event 50063 "Circle uncertain" before the arm moves, in real
/// time or not, so the twin does too, for a compiled program and for the driver's MoveC alike. The controller also plans the
/// whole circle before the arm moves: a circle that leaves the arm's reach or its joint limits anywhere along the arc stops
/// with event 50050 "Position outside reach" at its start, not only when its CirPoint or ToPoint is out of reach (issue 46,
/// ABB seed 1001871: a CirPoint behind the start point sweeps a large circle).
/// </summary>
internal static class RapidCircle
{
    /// <summary>The smallest angle between the CirPoint and the ToPoint seen from the start point, in degrees.</summary>
    public const double MinAngleDegrees = 1;

    /// <summary>Longest step between two points of the arc solved before the arm moves, in mm (and at least 8 points).</summary>
    public const double PathStepMm = 5;

    /// <summary>The controller's event "Circle uncertain" (motion domain 5, number 63).</summary>
    public const int UncertainEvent = 50063;

    /// <summary>The angle between <paramref name="cirPoint"/> and <paramref name="toPoint"/> seen from <paramref name="start"/>, in degrees (0 to 180).</summary>
    public static double AngleDegrees(Vector start, Vector cirPoint, Vector toPoint)
    {
        Vector u = cirPoint - start, w = toPoint - start;
        return Math.Atan2(Vector.Cross(u, w).Length, Vector.Dot(u, w)) * 180 / Math.PI;
    }

    /// <summary>
    /// The error that stops the task when the MoveC of <paramref name="call"/> from <paramref name="start"/> through
    /// <paramref name="cirPoint"/> to <paramref name="toPoint"/> (base frame, mm) breaks the 1° limit, or null.
    /// </summary>
    public static RapidRuntimeException? Uncertain(RapidCall call, Vector start, Vector cirPoint, Vector toPoint)
    {
        double angle = AngleDegrees(start, cirPoint, toPoint);
        if (angle >= MinAngleDegrees)
        {
            return null;
        }
        // An event of the motion, not a RAPID error an ERROR handler can take: the task stops (and the monitor's IError sees it).
        return new RapidRuntimeException(0, call.Line, FormattableString.Invariant(
            $"Circle uncertain: seen from the start point, the CirPoint and the ToPoint of MoveC are {Math.Round(angle, 3)}° apart; they must be at least {MinAngleDegrees}° apart (the three points are almost on one line)"))
        {
            Event = UncertainEvent,
            Fatal = true,
        };
    }

    /// <summary>
    /// Solves the arm along <paramref name="arc"/> from <paramref name="near"/> (the joints at its start), every
    /// <see cref="PathStepMm"/> at most; throws the <see cref="Twin.TwinMotionException"/> of the first point out of reach or
    /// beyond the joint limits. The tool centre must be set on <paramref name="arm"/>.
    /// </summary>
    public static void RequireReachable(Twin.TwinArm arm, Twin.TwinArc arc, Joints near)
    {
        int steps = Math.Clamp((int)Math.Ceiling(arc.LengthMm / PathStepMm), 8, 2_000);
        Joints joints = near;
        for (int i = 1; i < steps; i++)
        {
            joints = arm.Solve(arc.At((double)i / steps), joints);
            arm.RequireWithinLimits(joints);
        }
    }
}
