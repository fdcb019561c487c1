namespace Machina.Simulation.Rapid;

/// <summary>
/// The SmartGripper of a YuMi arm (the IRB 14000's servo gripper and its RAPID instructions, Hand_…), one per task: its fingers'
/// position in mm (0 closed, up to the physical limit), its maximum speed, hold force and whether it is calibrated. The twin has no
/// object between the fingers: a grip stops at its \targetPos, as if an object stood there, or closes (opens) fully.
/// </summary>
internal sealed class RapidHand
{
    /// <summary>The largest maximum speed (mm/s), hold force (N) and physical limit (mm) the gripper takes.</summary>
    public const double SpeedLimit = 25, ForceLimit = 20, StrokeLimit = 25;

    /// <summary>True once Hand_Initialize \Calibrate (or \Jog) ran.</summary>
    public bool Calibrated { get; set; }

    /// <summary>The fingers' position in mm.</summary>
    public double Position { get; set; }

    /// <summary>The force the fingers hold with now (N): the hold force after a grip, 0 after a move or a stop.</summary>
    public double Force { get; set; }

    /// <summary>The maximum finger speed, mm/s.</summary>
    public double MaxSpeed { get; set; } = 20;

    /// <summary>The hold force of a grip, N.</summary>
    public double HoldForce { get; set; } = 10;

    /// <summary>The physical limit of the stroke, mm.</summary>
    public double PhysicalLimit { get; set; } = StrokeLimit;
}
