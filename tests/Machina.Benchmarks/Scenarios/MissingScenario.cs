namespace Machina.Benchmarks;

/// <summary>Stands in for a scenario whose part of Machina is not in this build; it always reports "not available".</summary>
internal sealed class MissingScenario(string name, string title, int size, Target target, string reason) : Scenario
{
    public override string Name => name;
    public override string Title => title;
    public override int TargetSize => size;
    public override Target Target => target;
    public override string? Unavailable() => reason;
    public override Func<object?> Prepare(int size) => throw new NotSupportedException(reason);
}
