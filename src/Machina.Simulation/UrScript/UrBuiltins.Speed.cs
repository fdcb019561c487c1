using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>
    /// speedj and speedl (<see cref="UrTwinController.Speed"/>): the speed changes evenly from the arm's to the one asked (the
    /// leading joint at a for speedj; the tool's position at a and its turn at aRot for speedl, the slower leading) and stays after
    /// the call returned (after t, or once the speed is reached without t), until the thread's next motion or stop. speedl keeps the
    /// tool on its straight line however long it lasts (<see cref="UrToolSpeedPath"/>: the joints solved along the line, not a
    /// joint speed taken once at the call). The target speeds are the motion in progress's (zero while the arm stands).
    /// </summary>
    private static void AddSpeed(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "speedj", SpeedJ, R("qd"), R("a"), O("t", 0));
        Add(t, "speedl", SpeedL, R("xd"), R("a"), O("t", 0), O("aRot", NotGiven));
        Add(t, "get_target_joint_speeds", (m, line, a) => UrGeometry.FromJoints(m.Controller.JointSpeedsNow()));
        Add(t, "get_target_tcp_speed", (m, line, a) => new UrPose(m.Controller.TcpSpeedNow()));

        // A critical section keeps the controller from switching threads; the twin accepts both and does nothing more
        // (approximated: its other threads may still run between the section's statements).
        Add(t, "enter_critical", (m, line, a) => UrNone.Value);
        Add(t, "exit_critical", (m, line, a) => UrNone.Value);
    }

    private static object SpeedJ(UrMachine m, int line, object[] a)
    {
        double[] qd = Six(a, 0, line, "speedj", "qd");
        double time = SpeedTime(a, line, "speedj");
        double acceleration = Num(a, 1, line, "speedj", "a");
        FinishBlend(m, line);
        double[] now = m.Controller.JointSpeedsNow().ToArray(); // degrees per second
        double[] speeds = [.. qd.Select(r => r * 180 / Math.PI)];
        double change = Enumerable.Range(0, 6).Max(i => Math.Abs(speeds[i] - now[i])) * Math.PI / 180;
        RunSpeed(m, line, speeds, change > 0 && acceleration > 0 ? change / acceleration : 0, time, "speedj");
        return UrNone.Value;
    }

    private static object SpeedL(UrMachine m, int line, object[] a)
    {
        double[] xd = Six(a, 0, line, "speedl", "xd");
        double time = SpeedTime(a, line, "speedl");
        double acceleration = Num(a, 1, line, "speedl", "a");
        double turning = Given(a[3]) ? Positive(Num(a, 3, line, "speedl", "aRot"), line, "speedl", "aRot") : acceleration;
        FinishBlend(m, line);
        Unlocked(m, line, "speedl", (xd, acceleration, turning, time, line),
            static (c, s, token) => { c.ToolSpeed(s.xd, s.acceleration, s.turning, s.time, s.line, "speedl", token); return true; });
        return UrNone.Value;
    }

    /// <summary>Runs a speed motion (<see cref="UrTwinController.Speed"/>) with the other threads free meanwhile.</summary>
    private static void RunSpeed(UrMachine m, int line, double[] speeds, double ramp, double time, string function) =>
        Unlocked(m, line, function, (speeds, ramp, time, line, function),
            static (c, s, token) => { c.Speed(s.speeds, s.ramp, s.time, s.line, s.function, token); return true; });

    /// <summary>
    /// A motion of the calling thread starts: a speed motion of its own, or one whose thread was killed, stands where it is first;
    /// another, live thread's motion in progress is a runtime error (a UR's "Another thread is already controlling the robot.").
    /// </summary>
    private static void TakeControl(UrMachine m, int line, string function)
    {
        try
        {
            m.Controller.SettleCoast(m.Cancellation);
        }
        catch (TwinMotionException e)
        {
            throw new UrRuntimeException(line, $"{function}: {e.Message}");
        }
    }

    /// <summary>The acceleration (positive) and the optional time (zero or positive) of a speed command.</summary>
    private static double SpeedTime(object[] a, int line, string function)
    {
        double acceleration = Num(a, 1, line, function, "a");
        if (!(acceleration >= 0) || !double.IsFinite(acceleration))
        {
            // Zero is taken: UR's client library passes the largest speed change of a spline step, 0 when the speed holds.
            throw new UrRuntimeException(line, $"{function}: argument 'a' must be zero or positive");
        }
        double time = Num(a, 2, line, function, "t");
        return time >= 0 && double.IsFinite(time) ? time : throw new UrRuntimeException(line, $"{function}: argument 't' must be zero or positive");
    }
}
