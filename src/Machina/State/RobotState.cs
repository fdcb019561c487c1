using System.Collections.ObjectModel;

namespace Machina;

/// <summary>
/// An immutable picture of a robot's whole state at one moment (after an action, or as reported by the controller):
/// tool pose, joints, external axes, settings, tool, IO, temperatures and extrusion. Units: mm, degrees, mm/s, mm/s², °C.
/// </summary>
public sealed class RobotState
{
    internal RobotState(RobotCursor c)
    {
        Position = c.Position;
        Rotation = c.Rotation;
        Axes = c.Axes;
        ExternalAxesCartesian = c.ExternalAxesCartesian;
        ExternalAxesJoints = c.ExternalAxesJoints;
        ArmAngle = c.ArmAngle;
        Settings = c.CurrentSettings;
        Tool = c.Tool;
        DefinedTools = Freeze(c.Tools);
        DigitalOutputs = Freeze(c.DigitalOutputs);
        AnalogOutputs = Freeze(c.AnalogOutputs);
        ExtruderTemperature = c.Temperatures[(int)RobotPartType.Extruder];
        BedTemperature = c.Temperatures[(int)RobotPartType.Bed];
        ChamberTemperature = c.Temperatures[(int)RobotPartType.Chamber];
        IsExtruding = c.IsExtruding;
        ExtrudedLength = c.ExtrudedLength;
        SettingsDepth = c.SettingsStack.Count;
        LastAction = c.LastAction;
    }

    /// <summary>A read-only copy: user code cannot cast it back to a dictionary and change the snapshot (or, for the shared empty map, every snapshot).</summary>
    private static ReadOnlyDictionary<string, T> Freeze<T>(Dictionary<string, T> map) =>
        map.Count == 0 ? ReadOnlyDictionary<string, T>.Empty : new ReadOnlyDictionary<string, T>(new Dictionary<string, T>(map, map.Comparer));

    /// <summary>Tool tip position in mm (world frame), or null when unknown.</summary>
    public Vector? Position { get; }

    /// <summary>Tool orientation, or null when unknown.</summary>
    public Rotation? Rotation { get; }

    /// <summary>Joint angles in degrees, or null when unknown.</summary>
    public Joints? Axes { get; }

    /// <summary>External axis values used with Cartesian targets, or null when never set.</summary>
    public ExternalAxes? ExternalAxesCartesian { get; }

    /// <summary>External axis values used with joint targets, or null when never set.</summary>
    public ExternalAxes? ExternalAxesJoints { get; }

    /// <summary>Arm angle of a 7-axis arm in degrees, or null when never set.</summary>
    public double? ArmAngle { get; }

    /// <summary>Speed, acceleration, precision, motion type, reference frame and extrusion rate.</summary>
    public Settings Settings { get; }

    /// <summary>Speed, mm/s.</summary>
    public double Speed => Settings.Speed;

    /// <summary>Acceleration, mm/s² (0 = controller default).</summary>
    public double Acceleration => Settings.Acceleration;

    /// <summary>Blend radius, mm.</summary>
    public double Precision => Settings.Precision;

    /// <summary>Linear or joint motion.</summary>
    public MotionType MotionType => Settings.MotionType;

    /// <summary>Frame of relative actions.</summary>
    public ReferenceCS ReferenceCS => Settings.ReferenceCS;

    /// <summary>The attached tool, or null.</summary>
    public Tool? Tool { get; }

    /// <summary>Tools defined so far, by name.</summary>
    public IReadOnlyDictionary<string, Tool> DefinedTools { get; }

    /// <summary>Digital outputs written so far, by pin (tool pins are prefixed "tool:").</summary>
    public IReadOnlyDictionary<string, bool> DigitalOutputs { get; }

    /// <summary>Analog outputs written so far, by pin (tool pins are prefixed "tool:").</summary>
    public IReadOnlyDictionary<string, double> AnalogOutputs { get; }

    /// <summary>Extruder temperature, °C.</summary>
    public double ExtruderTemperature { get; }

    /// <summary>Bed temperature, °C.</summary>
    public double BedTemperature { get; }

    /// <summary>Chamber temperature, °C.</summary>
    public double ChamberTemperature { get; }

    /// <summary>True while extruding.</summary>
    public bool IsExtruding { get; }

    /// <summary>Filament pushed so far, mm.</summary>
    public double ExtrudedLength { get; }

    /// <summary>How many PushSettings are waiting for their PopSettings.</summary>
    public int SettingsDepth { get; }

    /// <summary>The last action applied, or null.</summary>
    public RobotAction? LastAction { get; }

    /// <summary>Short text with pose, joints and settings.</summary>
    public override string ToString() =>
        $"State[position {Position?.ToString() ?? "unknown"}, rotation {Rotation?.ToQuaternionString() ?? "unknown"}, axes {Axes?.ToString() ?? "unknown"}, {Settings}]";
}
