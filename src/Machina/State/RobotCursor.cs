namespace Machina;

/// <summary>
/// The full state of a robot as a sequence of actions changes it. Mutable and allocation-free per action so that
/// millions of actions stay cheap; <see cref="Snapshot"/> makes the immutable <see cref="RobotState"/> that users see.
/// </summary>
internal sealed partial class RobotCursor
{
    /// <summary>Deepest allowed nesting of PushSettings.</summary>
    internal const int MaxSettingsDepth = 1024;

    internal Vector? Position { get; private set; }
    internal Vector? PrevPosition { get; private set; }
    internal Rotation? Rotation { get; private set; }
    internal Rotation? PrevRotation { get; private set; }
    internal Joints? Axes { get; private set; }
    internal Joints? PrevAxes { get; private set; }
    private double _speed;
    internal double Speed => _speed;
    private double _acceleration;
    internal double Acceleration => _acceleration;
    private double _precision;
    internal double Precision => _precision;
    private MotionType _motionType;
    internal MotionType MotionType => _motionType;
    private ReferenceCS _referenceCS;
    internal ReferenceCS ReferenceCS => _referenceCS;
    internal Tool? Tool { get; private set; }
    internal readonly Dictionary<string, Tool> Tools = new(StringComparer.Ordinal);
    internal ExternalAxes? ExternalAxesCartesian { get; private set; }
    internal ExternalAxes? ExternalAxesJoints { get; private set; }
    internal double? ArmAngle { get; private set; }
    internal readonly Dictionary<string, bool> DigitalOutputs = new(StringComparer.Ordinal);
    internal readonly Dictionary<string, double> AnalogOutputs = new(StringComparer.Ordinal);
    internal readonly double[] Temperatures = new double[3];
    private bool _isExtruding;
    internal bool IsExtruding => _isExtruding;
    private double _extrusionRate;
    internal double ExtrusionRate => _extrusionRate;
    internal double ExtrudedLength { get; private set; }
    internal double PrevExtrudedLength { get; private set; }
    internal readonly Stack<Settings> SettingsStack = new();
    /// <summary>The settings in force just before the last PopSettings (a compiler re-emits what changed).</summary>
    internal Settings? SettingsBeforeLastPop { get; private set; }
    /// <summary>After an arc: the world position of its through point.</summary>
    internal Vector? ArcThrough { get; private set; }
    /// <summary>After an arc: the orientation at its through point.</summary>
    internal Rotation? ArcThroughRotation { get; private set; }
    /// <summary>Length of the tool-tip path of the last motion, mm (arc length for arcs), or null when unknown.</summary>
    internal double? LastPathLength { get; private set; }
    internal RobotAction? LastAction { get; private set; }

    /// <summary>Receives warnings about actions that were applied but may surprise the user; may be null.</summary>
    internal Action<RobotAction, string>? Warn;

    /// <summary>
    /// Receives what the robot's log shows as a warning but a compiled program does not, because it is the usual order of
    /// things (a tool attached before the first absolute motion); may be null.
    /// </summary>
    internal Action<RobotAction, string>? Notice;

    /// <summary>A cursor in Machina's initial state: position unknown, tool pointing down, 20 mm/s, 30 mm/s², 5 mm, linear, world.</summary>
    internal RobotCursor() => Reset();

    /// <summary>The settings currently in force.</summary>
    internal Settings CurrentSettings => new(Speed, Acceleration, Precision, MotionType, ReferenceCS, ExtrusionRate);

    /// <summary>Puts the cursor back in the initial state.</summary>
    internal void Reset()
    {
        Position = PrevPosition = null;
        Rotation = PrevRotation = Machina.Rotation.FlippedAroundY;
        Axes = PrevAxes = null;
        ApplySettings(Settings.Default);
        Tool = null;
        Tools.Clear();
        ExternalAxesCartesian = ExternalAxesJoints = null;
        ArmAngle = null;
        DigitalOutputs.Clear();
        AnalogOutputs.Clear();
        Array.Clear(Temperatures);
        _isExtruding = false;
        ExtrudedLength = PrevExtrudedLength = 0;
        SettingsStack.Clear();
        SettingsBeforeLastPop = null;
        ArcThrough = null;
        ArcThroughRotation = null;
        LastPathLength = null;
        LastAction = null;
    }

    /// <summary>Makes this cursor an exact copy of <paramref name="other"/>, model included (its warning sink and strictness are kept).</summary>
    internal void CopyFrom(RobotCursor other)
    {
        Position = other.Position; PrevPosition = other.PrevPosition;
        Rotation = other.Rotation; PrevRotation = other.PrevRotation;
        Axes = other.Axes; PrevAxes = other.PrevAxes;
        ApplySettings(other.CurrentSettings);
        Tool = other.Tool;
        Tools.Clear();
        foreach (var kv in other.Tools) { Tools[kv.Key] = kv.Value; }
        ExternalAxesCartesian = other.ExternalAxesCartesian; ExternalAxesJoints = other.ExternalAxesJoints;
        ArmAngle = other.ArmAngle;
        DigitalOutputs.Clear();
        foreach (var kv in other.DigitalOutputs) { DigitalOutputs[kv.Key] = kv.Value; }
        AnalogOutputs.Clear();
        foreach (var kv in other.AnalogOutputs) { AnalogOutputs[kv.Key] = kv.Value; }
        Array.Copy(other.Temperatures, Temperatures, Temperatures.Length);
        _isExtruding = other.IsExtruding;
        ExtrudedLength = other.ExtrudedLength; PrevExtrudedLength = other.PrevExtrudedLength;
        SettingsStack.Clear();
        if (other.SettingsStack.Count > 0)
        {
            // Bottom first. Not through LINQ's Reverse: its iterator over a stack of structs was JIT-compiled (a dozen methods)
            // for every compile of a fresh process, almost always for an empty stack.
            Settings[] saved = other.SettingsStack.ToArray();
            for (int i = saved.Length - 1; i >= 0; i--)
            {
                SettingsStack.Push(saved[i]);
            }
        }
        SettingsBeforeLastPop = other.SettingsBeforeLastPop;
        ArcThrough = other.ArcThrough; ArcThroughRotation = other.ArcThroughRotation;
        LastPathLength = other.LastPathLength;
        LastAction = other.LastAction;
        Model = other.Model;
        LastIssues = other.LastIssues;
    }

    private void ApplySettings(Settings s)
    {
        _speed = s.Speed;
        _acceleration = s.Acceleration;
        _precision = s.Precision;
        _motionType = s.MotionType;
        _referenceCS = s.ReferenceCS;
        _extrusionRate = s.ExtrusionRate;
    }

    /// <summary>An immutable copy of the whole state.</summary>
    internal RobotState Snapshot() => new(this);

    /// <summary>Debug text: motion type, position, rotation, joints, acceleration, speed, precision and tool.</summary>
    public override string ToString() =>
        $"{MotionType} p{Position?.ToString() ?? "null"} r{Rotation?.ToQuaternionString() ?? "null"} j{Axes?.ToString() ?? "null"} " +
        $"a{Num.G(Acceleration)} v{Num.G(Speed)} p{Num.G(Precision)}{(Tool is null ? "" : " t" + Tool.Name)}";
}
