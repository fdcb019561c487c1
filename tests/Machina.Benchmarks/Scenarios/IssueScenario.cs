namespace Machina.Benchmarks;

/// <summary>Issues relative moves offline with <c>Robot.Move</c>: each is checked against the state, applied and kept for compiling.</summary>
internal sealed class IssueScenario : Scenario
{
    public override string Name => "issue";
    public override string Title => "Issue relative moves offline (Robot.Move)";
    public override int TargetSize => 1_000_000;
    public override Target Target { get; } = Target.Seconds(0.5, 1_000_000, "<= 0.5 s per 10^6, <= 200 B/action", bytesPerUnit: 200);

    public override Func<object?> Prepare(int size) => () => Workloads.IssueToolpath("ABB", size);
}
