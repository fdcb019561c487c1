namespace Machina;

/// <summary>A heated part of a 3D printer.</summary>
public enum RobotPartType
{
    /// <summary>The hot end that melts the filament.</summary>
    Extruder,
    /// <summary>The print bed.</summary>
    Bed,
    /// <summary>The printer's enclosure.</summary>
    Chamber,
}
