namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>
    /// speedj and speedl as the twin approximates them: with a time <c>t</c>, the arm moves at the given speed for that time (joints
    /// by qd·t; the tool by xd·t, its rotation vector added); without one it stands (a controller would keep the speed until the next
    /// motion command; the twin has no open-ended motion). The target speeds are the motion in progress's (zero while the arm stands).
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
        FinishBlend(m, line);
        if (time > 0)
        {
            Joints to = m.Controller.Arm.Joints + Joints.FromArray([.. qd.Select(r => r * 180 / Math.PI * time)]);
            Move(m, line, to, time, "speedj");
        }
        return UrNone.Value;
    }

    private static object SpeedL(UrMachine m, int line, object[] a)
    {
        double[] xd = Six(a, 0, line, "speedl", "xd");
        double time = SpeedTime(a, line, "speedl");
        FinishBlend(m, line);
        if (time > 0)
        {
            double[] pose = UrValue.Six(UrGeometry.FromPose(m.Controller.Arm.Tcp), line, "speedl");
            double[] to = [.. pose.Select((p, i) => p + xd[i] * time)];
            return MoveLinear(m, line, [new UrPose(to), a[1], 1.0, time, 0.0], "speedl");
        }
        return UrNone.Value;
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
