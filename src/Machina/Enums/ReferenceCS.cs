namespace Machina;

/// <summary>The frame in which relative moves and rotations are expressed.</summary>
public enum ReferenceCS
{
    /// <summary>The robot's world (base) frame (default).</summary>
    World,
    /// <summary>The tool's own frame: "forward" means along the tool.</summary>
    Local,
}
