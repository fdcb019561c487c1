namespace Machina.Simulation.Krl;

/// <summary>What a controller gives every program: its system variables, its configured signals and its built-in routines.</summary>
internal sealed class KrlEnvironment
{
    /// <summary>The system variables ($BASE, $OUT…), by name.</summary>
    public Dictionary<string, KrlCell> System { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The signals of the IO configuration (e.g. DO_Gripper for an output), by name.</summary>
    public Dictionary<string, KrlCell> Signals { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The built-in routines, by name.</summary>
    public Dictionary<string, KrlBuiltin> Builtins { get; } = new(StringComparer.OrdinalIgnoreCase);
}
