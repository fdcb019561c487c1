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
        scenarios.Add(new ParseScenario(workloads));
        scenarios.Add(new ActionTextScenario(workloads, describe: false));
        scenarios.Add(new ActionTextScenario(workloads, describe: true));
        return scenarios;
    }
}
