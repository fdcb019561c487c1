namespace Machina;

/// <summary>
/// A dry run: actions tried one by one on a copy of a robot's state, as the robot would apply them, to learn before anything
/// moves what would be refused, what the arm cannot do and where it ends up. Nothing is issued, sent or compiled.
/// </summary>
/// <remarks>
/// A trial never refuses an action for the arm's problems, even for a robot in strict mode: it lists them in
/// <see cref="TrialStep.Issues"/> and the caller decides. Not thread-safe: one caller at a time.
/// </remarks>
public sealed class ProgramTrial
{
    private readonly RobotCursor _cursor;
    private readonly IActionStream? _stream;
    private readonly List<string> _warnings = [];
    private readonly MotionTiming _timing;
    private readonly BlendTiming? _blends;
    private double _seconds;

    /// <summary>
    /// A trial from Machina's initial state (no position or joints known yet), with the arm model <paramref name="model"/> (or none);
    /// durations are those of the model's brand of controller.
    /// </summary>
    public ProgramTrial(RobotModel? model)
        : this(new RobotCursor { Model = model }, null, TimingOf(model))
    {
    }

    /// <summary>A trial from <paramref name="start"/> (copied, model included), checked also by what an online robot's <paramref name="stream"/> cannot run, timed by <paramref name="timing"/>.</summary>
    internal ProgramTrial(RobotCursor start, IActionStream? stream, MotionTiming timing)
    {
        _timing = timing;
        _blends = timing.NewBlendTiming();
        _cursor = new RobotCursor();
        _cursor.CopyFrom(start);
        _cursor.Strict = false;
        _cursor.Warn = (_, message) => _warnings.Add(message);
        _stream = stream;
    }

    /// <summary>How many actions were applied so far (refused ones are not counted).</summary>
    public int AppliedCount { get; private set; }

    /// <summary>
    /// The estimated time of the actions applied so far: each motion at the program's speed and acceleration as the brand's
    /// controller runs it (joint moves from the arm's joint speeds where the brand does), plus the waits. Blends shorten it where the
    /// brand's blends are modelled (UR): the arm does not stop at a blended waypoint.
    /// </summary>
    public TimeSpan EstimatedDuration => TimeSpan.FromSeconds(_seconds);

    /// <summary>How many applied motions the estimate leaves out because a pose or the joints they are timed by were not known.</summary>
    public int UntimedMotions { get; private set; }

    /// <summary>The arm model the motions are checked with, or null (then no kinematics).</summary>
    public RobotModel? Model => _cursor.Model;

    /// <summary>The tool tip's position after the last applied action, or null while unknown.</summary>
    public Vector? Position => _cursor.Position;

    /// <summary>The tool's orientation after the last applied action, or null while unknown.</summary>
    public Rotation? Rotation => _cursor.Rotation;

    /// <summary>The joint angles after the last applied action, degrees, or null while unknown.</summary>
    public Joints? Axes => _cursor.Axes;

    /// <summary>The joint angles before the last applied motion, or null while unknown.</summary>
    public Joints? PreviousAxes => _cursor.PrevAxes;

    /// <summary>After an arc: the world position of its through point (else whatever the last arc left, or null).</summary>
    public Vector? ArcThrough => _cursor.ArcThrough;

    /// <summary>The tool attached after the last applied action, or null.</summary>
    public Tool? Tool => _cursor.Tool;

    /// <summary>The motion type (linear or joint) in force after the last applied action.</summary>
    public MotionType MotionType => _cursor.MotionType;

    /// <summary>True while extruding (3D printers and extruders).</summary>
    public bool IsExtruding => _cursor.IsExtruding;

    /// <summary>The whole state after the last applied action (a copy; for a few fields the properties above are cheaper).</summary>
    public RobotState State => _cursor.Snapshot();

    /// <summary>True for the actions that move the robot (translations, rotations, transformations, joint moves, arcs).</summary>
    public static bool IsMotion(RobotAction action) => RobotCursor.IsMotion(action);

    /// <summary>
    /// Tries <paramref name="action"/> after the actions applied so far: applied when it can be (the state moves on), else refused
    /// with the reason. The step lists what deserves a look: warnings and the arm's issues. A refused action leaves the state as it
    /// was, except one only an online robot's driver refuses for the state it leaves (e.g. a UR output value): that state is kept.
    /// </summary>
    /// <exception cref="ArgumentNullException"><paramref name="action"/> is null.</exception>
    public TrialStep Try(RobotAction action)
    {
        ArgumentNullException.ThrowIfNull(action);
        _warnings.Clear();
        (Vector? position, Rotation? rotation, Joints? axes) = (_cursor.Position, _cursor.Rotation, _cursor.Axes);
        string? refusal = _stream?.WhyCannotStream(action) ?? _cursor.TryApply(action) ?? _stream?.WhyCannotSend(action, _cursor);
        if (refusal is not null)
        {
            return new TrialStep(action, refusal, [], []);
        }
        AppliedCount++;
        double? seconds = SecondsOf(action, position, rotation, axes);
        if (seconds is double s)
        {
            _seconds += s;
        }
        else
        {
            UntimedMotions++;
        }
        return new TrialStep(action, null, _warnings.Count == 0 ? [] : [.. _warnings], _cursor.LastIssues)
        {
            Duration = seconds is double d ? TimeSpan.FromSeconds(d) : null,
        };
    }

    /// <summary>Seconds the applied <paramref name="action"/> takes from the pose it started at; 0 for an action that takes no time, null for a motion that cannot be timed.</summary>
    private double? SecondsOf(RobotAction action, Vector? position, Rotation? rotation, Joints? axes)
    {
        if (!RobotCursor.IsMotion(action))
        {
            _blends?.NotMotion(action);
            return action is ActionWait wait ? wait.Millis / 1000.0 : 0;
        }
        bool joint = action is ActionAxes || (_cursor.MotionType == MotionType.Joint && action is not ActionArcMotion);
        var motion = new TimedMotion(position, rotation, axes, _cursor.Position, _cursor.Rotation, _cursor.Axes,
            joint ? null : _cursor.LastPathLength, joint, _cursor.Speed, _cursor.Acceleration);
        double? plain = _timing.Seconds(motion, _cursor.Model);
        return _blends is null ? plain : _blends.Seconds(action, motion, _cursor.Precision, plain);
    }

    /// <summary>The timing of the brand that makes <paramref name="model"/>, or the generic one.</summary>
    internal static MotionTiming TimingOf(RobotModel? model) =>
        model is null ? MotionTiming.Generic
            : BrandRegistry.All.FirstOrDefault(b => string.Equals(b.ModelBrand, model.Brand, StringComparison.OrdinalIgnoreCase))?.Timing ?? MotionTiming.Generic;
}
