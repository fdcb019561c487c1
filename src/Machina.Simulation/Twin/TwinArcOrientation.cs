namespace Machina.Simulation.Twin;

/// <summary>How the tool turns along a circular motion (<see cref="TwinArc"/>).</summary>
internal enum TwinArcOrientation
{
    /// <summary>Evenly from the start to the end orientation in the base frame (UR movec mode 0, KUKA CIRC space-related).</summary>
    Even,

    /// <summary>
    /// Evenly relative to the circle (ABB MoveC): the orientation relative to the path turns evenly from the start's to the end's, so
    /// a tool that has the same orientation to the path at both ends keeps it all the way.
    /// </summary>
    PathRelative,

    /// <summary>Turning with the circle, keeping the start's orientation to the path; the end orientation is not used (UR movec mode 1).</summary>
    FixedToPath,
}
