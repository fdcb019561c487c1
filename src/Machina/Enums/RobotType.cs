namespace Machina;

/// <summary>The kind of device a robot program is written for; it selects the language Machina compiles to.</summary>
public enum RobotType
{
    /// <summary>A human-readable listing (no robot language).</summary>
    HUMAN,
    /// <summary>Machina's own instruction text, which can be read back with <c>Do</c>.</summary>
    MACHINA,
    /// <summary>ABB industrial arms (RAPID).</summary>
    ABB,
    /// <summary>Universal Robots arms (URScript).</summary>
    UR,
    /// <summary>KUKA industrial arms (KRL).</summary>
    KUKA,
    /// <summary>ZMorph 3D printers (G-code).</summary>
    ZMORPH,
    /// <summary>Generic Marlin-flavoured 3D printers (G-code).</summary>
    MARLIN,
}
