namespace Machina.Simulation.Rapid;

/// <summary>The path levels of a motion task (RAPID StorePath, RestoPath, ClearPath).</summary>
internal sealed partial class RapidTask
{
    /// <summary>True once the program cleared the path of the motion under way (ClearPath) since the last StorePath or RestoPath.</summary>
    public bool PathCleared { get; set; }

    /// <summary>The motion StorePath stored (it was held, its path was cleared), or null when no path is stored.</summary>
    public (bool Held, bool Cleared)? StoredPath { get; set; }
}
