namespace Machina.Benchmarks;

/// <summary>
/// A part of compiling, measured alone to show where compile time goes: writing each move's instruction text
/// (<c>ToInstruction</c>) or its description (<c>Describe</c>) without keeping the strings. Informative, no target.
/// </summary>
internal sealed class ActionTextScenario(Workloads workloads, bool describe) : Scenario
{
    public override string Name => describe ? "part-describe" : "part-instruction";
    public override string Title => describe ? "Describe each move (Describe), strings dropped" : "Instruction text of each move (ToInstruction), strings dropped";
    public override string Unit => "move";
    public override int TargetSize => 1_000_000;
    public override IReadOnlyList<int> ScalingSizes => [];
    public override Target? Target => null;

    public override Func<object?> Prepare(int size)
    {
        IReadOnlyList<RobotAction> actions = workloads.Toolpath(size).GetProgramActions();
        return () =>
        {
            long characters = 0;
            foreach (RobotAction action in actions)
            {
                characters += (describe ? action.Describe() : action.ToInstruction()).Length;
            }
            return characters;
        };
    }
}
