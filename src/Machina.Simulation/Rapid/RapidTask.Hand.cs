namespace Machina.Simulation.Rapid;

internal sealed partial class RapidTask
{
    /// <summary>The SmartGripper this task's arm carries (the Hand_… instructions).</summary>
    public RapidHand Hand { get; } = new();
}
