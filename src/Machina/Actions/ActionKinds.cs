namespace Machina;

/// <summary>For the switches over action kinds (cursor, writers, encoders): what to do with a kind a switch does not name.</summary>
internal static class ActionKinds
{
    /// <summary>
    /// The error a switch throws for an action kind it does not name: every switch names every kind it handles, so a new
    /// kind fails loudly (and the all-kinds test fails) instead of being dropped without a word.
    /// </summary>
    internal static InvalidOperationException Unhandled(RobotAction action, string where) =>
        new($"{where} does not handle {action.GetType().Name} actions ({action.ToInstruction()}); this is a bug in Machina, please report it.");
}
