namespace Machina.Simulation.Rapid;

/// <summary>The modules of one task, bound: every name resolved and every type checked, its data initialised.</summary>
internal sealed class RapidProgram
{
    /// <summary>The modules, in load order.</summary>
    public List<RapidModule> Modules { get; } = [];

    /// <summary>The global (non-LOCAL) routines by name.</summary>
    public Dictionary<string, RapidRoutine> Routines { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The task's global data by name (predefined data included).</summary>
    public Dictionary<string, RapidCell> Globals { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The task's LOCAL module data by name (the first module's when two have the same name), for GetDataVal and SetDataVal.</summary>
    public Dictionary<string, RapidCell> ModuleData { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The names of the predefined data: a program's own global data of the same name hides them, as in RAPID's scope rules.</summary>
    public HashSet<string> Predefined { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The record types by name (predefined ones included).</summary>
    public Dictionary<string, RapidType> Types { get; } = new(RapidTypes.All, StringComparer.OrdinalIgnoreCase);

    /// <summary>The task's <c>ERRNO</c>.</summary>
    public RapidCell Errno { get; } = new("ERRNO", new RapidDataType(RapidTypes.All["errnum"]), RapidStorage.Var, 0.0);

    /// <summary>The routine called <paramref name="name"/> (global), or null.</summary>
    public RapidRoutine? Find(string name) => Routines.GetValueOrDefault(name);
}
