namespace Machina.Benchmarks;

/// <summary>Every scenario of the harness, in the order they run.</summary>
internal static class Catalog
{
    public static IReadOnlyList<Scenario> All(Workloads workloads)
    {
        RobotType[] languages = [RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.ZMORPH, RobotType.MARLIN, RobotType.HUMAN, RobotType.MACHINA];
        var scenarios = new List<Scenario> { new IssueScenario() };
        scenarios.AddRange(languages.Select(l => new CompileScenario(workloads, l, toFolder: false)));
        scenarios.AddRange(languages.Select(l => new CompileScenario(workloads, l, toFolder: true)));
        scenarios.AddRange(languages.Select(l => new FileCompileScenario(l)));
        scenarios.Add(new ParseScenario(workloads));
        scenarios.Add(new CliCompileScenario());
        scenarios.AddRange(new[] { RobotType.ABB, RobotType.UR, RobotType.KUKA }.Select(b => new HostOnlyScenario(b)));
#if MACHINA_ONLINE
        scenarios.Add(new StreamScenario(wideWindow: false));
        scenarios.Add(new StreamScenario(wideWindow: true));
        scenarios.Add(new StreamScenario(wideWindow: false, ur: true));
        scenarios.Add(new StreamScenario(wideWindow: true, ur: true));
        scenarios.Add(new StreamScenario(wideWindow: true, ur: true, twin: true));
        scenarios.Add(new UrTwinLoadScenario());
        scenarios.Add(new KrlTwinStreamScenario());
        scenarios.Add(new KrlTwinStreamScenario(wideWindow: false));
        scenarios.Add(new RapidLoadScenario());
        scenarios.AddRange(new[] { RobotType.ABB, RobotType.UR, RobotType.KUKA }.Select(b => new PlainProgramScenario(b)));
        scenarios.AddRange(new[] { RobotType.ABB, RobotType.UR, RobotType.KUKA }.Select(b => new PlainProgramScenario(b, connectOnce: true)));
#else
        scenarios.Add(new MissingScenario("stream", "Stream moves to the virtual ABB controller", 100_000, StreamTarget, "the virtual ABB controller is not in this build."));
#endif
#if MACHINA_KINEMATICS
        scenarios.Add(new InverseKinematicsScenario("ik-abb", "IRB 120", new Joints(10, 20, 30, 40, 50, 60)));
        scenarios.Add(new InverseKinematicsScenario("ik-kuka", "KR 6 R900 sixx", new Joints(10, -70, 80, 40, 50, 60)));
        scenarios.Add(new InverseKinematicsScenario("ik-ur", "UR5e", new Joints(10, -60, 80, -110, -90, 30)));
#else
        scenarios.Add(new MissingScenario("ik", "Inverse kinematics, all solutions of one pose", 200_000, IkTarget, "kinematics are not in this build."));
#endif
        scenarios.Add(new ActionTextScenario(workloads, describe: false));
        scenarios.Add(new ActionTextScenario(workloads, describe: true));
        return scenarios;
    }

    /// <summary>The streaming target: at least 20,000 actions per second acknowledged.</summary>
    public static Target StreamTarget { get; } = Target.PerSecond(20_000, ">= 20,000 actions/s acknowledged");

    /// <summary>Issue 45's target for the plain program: at most 20 µs of processor time per action, host and twin together.</summary>
    public static Target PlainProgramTarget { get; } = Target.CpuMicroseconds(20, "<= 20 us CPU per action (host + twin)");

    /// <summary>The host's share of the plain program's budget: the host alone must stay well under the 20 µs of host and twin together.</summary>
    public static Target HostOnlyTarget { get; } = Target.CpuMicroseconds(10, "<= 10 us CPU per action (host alone)");

    /// <summary>The inverse kinematics target: all solutions of one pose in at most 5 µs.</summary>
    public static Target IkTarget { get; } = Target.Microseconds(5, "<= 5 us per pose");
}
