namespace Machina.Simulation.Twin;

/// <summary>
/// A motion's own path (fraction of the way to joints: a blend) as the arm gets it: made (<see cref="Make"/>) only when the arm is
/// part-way along it, so that a motion in one step of program time makes no object for it.
/// </summary>
internal interface ITwinPath
{
    /// <summary>The path, or null for none (the motion goes straight in joint space, or along the tool's line or arc).</summary>
    Func<double, Joints>? Make();
}

/// <summary>A path given as it is (or none).</summary>
internal readonly struct GivenPath(Func<double, Joints>? path) : ITwinPath
{
    /// <inheritdoc/>
    public Func<double, Joints>? Make() => path;
}
