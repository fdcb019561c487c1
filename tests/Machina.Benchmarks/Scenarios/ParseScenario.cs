namespace Machina.Benchmarks;

/// <summary>Parses an instruction file (one statement per line, with comments and strings) with <c>Instructions.Parse</c>.</summary>
internal sealed class ParseScenario(Workloads workloads) : Scenario
{
    public override string Name => "parse";
    public override string Title => "Parse an instruction file (Instructions.Parse)";
    public override string Unit => "line";
    public override int TargetSize => 1_000_000;
    public override Target Target { get; } = Target.Seconds(1, 1_000_000, "<= 1 s per 10^6 lines");

    public override Func<object?> Prepare(int size)
    {
        string text = workloads.InstructionText(size);
        return () => Instructions.Parse(text);
    }
}
