namespace Machina.Simulation.Twin;

/// <summary>
/// The arm of a twin controller: its model's kinematics (shared with the library), the joints it is at, the active tool centre
/// point and payload, and a trace of what it did. Language interpreters move it; it refuses what the real arm cannot do.
/// </summary>
internal sealed partial class TwinArm
{
    private readonly Lock _gate = new();
    private readonly List<TwinTraceEntry> _trace = [];
    private Joints _joints;

    // The last flange pose computed and its joints (under the gate): see FlangeAt.
    private Joints _forwardJoints;
    private Pose _forwardFlange;
    private bool _hasForward;

    // The last joints found within the limits (under the gate): see RequireWithinLimits.
    private Joints _withinJoints;
    private bool _hasWithin;

    /// <summary>An arm of <paramref name="model"/> at <paramref name="start"/> joints (degrees).</summary>
    public TwinArm(RobotModel model, Joints start, TwinClock clock)
    {
        Model = model;
        Clock = clock;
        if (!model.IsWithinLimits(start))
        {
            throw new ArgumentException($"The start joints {start} are outside the limits of the {model}.", nameof(start));
        }
        _joints = start;
    }

    /// <summary>The robot model (kinematics, joint limits).</summary>
    public RobotModel Model { get; }

    /// <summary>The controller's clock.</summary>
    public TwinClock Clock { get; }

    /// <summary>The joints now, in degrees.</summary>
    public Joints Joints
    {
        get
        {
            lock (_gate)
            {
                return JointsNow();
            }
        }
    }

    /// <summary>The joints now (under the gate).</summary>
    private Joints JointsNow() =>
        _moving is { } moving ? moving.At(Clock.Time.GetElapsedTime(moving.Started).TotalSeconds) : _paced is { } paced ? paced.At(Clock.Seconds) : _joints;

    /// <summary>
    /// The joints now and the tool centre point at them (mm, base frame), read in one look at the gate: <see cref="Joints"/> and
    /// <see cref="Tcp"/> each took it, and the tool centre's flange pose took it again (a KRL position read did all three).
    /// </summary>
    public (Joints Joints, Pose Tcp) Now
    {
        get
        {
            Joints joints;
            Pose flange;
            bool known;
            lock (_gate)
            {
                joints = JointsNow();
                known = KeptFlange(joints, out flange);
            }
            return (joints, (known ? flange : Forward(joints)) * ToolCenter);
        }
    }

    /// <summary>The active tool centre point, relative to the flange (mm).</summary>
    public Pose ToolCenter { get; set; } = Pose.Identity;

    /// <summary>
    /// How many trace entries are kept, the oldest dropped first (0, the default: all). A controller that serves a stream of
    /// millions of moves sets it so that its memory stays bounded; a verification keeps all.
    /// </summary>
    public int MaxTrace { get; init; }

    /// <summary>The payload mass in kg.</summary>
    public double PayloadKg { get; set; }

    /// <summary>The flange pose now (mm, base frame).</summary>
    public Pose Flange => FlangeAt(Joints);

    /// <summary>
    /// The flange pose at <paramref name="joints"/> (mm, base frame): the model's forward kinematics, kept for the last joints asked.
    /// A motion asks for the pose of the joints it starts from several times (the program reads the TCP, the motion its start and
    /// end, the trace its end, which the next motion starts from): with the same joints to the last bit, the kept pose is the
    /// one the kinematics would compute again.
    /// </summary>
    public Pose FlangeAt(Joints joints)
    {
        lock (_gate)
        {
            if (KeptFlange(joints, out Pose kept))
            {
                return kept;
            }
        }
        return Forward(joints);
    }

    /// <summary>The flange pose kept for <paramref name="joints"/> when they are the last ones asked (under the gate).</summary>
    private bool KeptFlange(Joints joints, out Pose flange)
    {
        flange = _forwardFlange;
        return _hasForward && SameBits.Of(joints, _forwardJoints);
    }

    /// <summary>The forward kinematics of <paramref name="joints"/> (not under the gate), kept as <see cref="FlangeAt"/> says.</summary>
    private Pose Forward(Joints joints)
    {
        Pose flange = Model.Kinematics.Forward(joints);
        lock (_gate)
        {
            KeepFlange(joints, flange);
        }
        return flange;
    }

    /// <summary>Keeps <paramref name="flange"/>, the forward kinematics of <paramref name="joints"/>, for <see cref="FlangeAt"/> (under the gate).</summary>
    private void KeepFlange(Joints joints, Pose flange)
    {
        ForwardSolves++;
        (_forwardJoints, _forwardFlange, _hasForward) = (joints, flange, true);
    }

    /// <summary>How many times the forward kinematics ran for this arm (<see cref="FlangeAt"/>'s misses; tests count them).</summary>
    internal int ForwardSolves { get; private set; }

    /// <summary>How many times <see cref="RequireWithinLimits"/> looked at the joint limits (its misses; tests count them).</summary>
    internal int LimitChecks { get; private set; }

    /// <summary>The tool centre point now (mm, base frame).</summary>
    public Pose Tcp => Now.Tcp;

    /// <summary>A copy of every traced step so far.</summary>
    public IReadOnlyList<TwinTraceEntry> Trace
    {
        get
        {
            lock (_gate)
            {
                return [.. _trace];
            }
        }
    }

    /// <summary>The joints (degrees) that put the tool centre point at <paramref name="tcp"/>, nearest to <paramref name="near"/>.</summary>
    /// <exception cref="TwinMotionException">The pose is out of reach or needs a joint beyond its limits.</exception>
    public Joints Solve(Pose tcp, Joints near)
    {
        Pose flange = tcp * ToolCenter.Inverse();
        if (!flange.Position.IsFinite)
        {
            throw new TwinMotionException("no inverse kinematics solution: the target pose is out of reach (a coordinate is too large)");
        }
        Joints? solution = Model.Kinematics.Closest(flange, near);
        if (solution is { } found)
        {
            return found;
        }
        KinematicIssue? why = Model.Kinematics.WhyNoSolution(flange);
        throw new TwinMotionException(why is { Kind: KinematicIssueKind.JointLimit }
            ? $"no inverse kinematics solution within the joint limits for the target pose ({why})"
            : "no inverse kinematics solution: the target pose is out of reach");
    }

    /// <summary>Checks that <paramref name="joints"/> are within the joint limits.</summary>
    /// <exception cref="TwinMotionException">A joint is beyond its limit.</exception>
    /// <remarks>
    /// A motion's target is checked where the language asks (to raise its own error) and again where the arm starts the motion:
    /// joints the same to the bit as the last ones found within the limits are not looked at again (the limits do not change).
    /// </remarks>
    public void RequireWithinLimits(Joints joints)
    {
        lock (_gate)
        {
            if (_hasWithin && SameBits.Of(joints, _withinJoints))
            {
                return;
            }
            LimitChecks++;
            // Twelve compares: looked at and kept in the same look at the gate (a second look kept them before).
            if (Model.IsWithinLimits(joints))
            {
                (_withinJoints, _hasWithin) = (joints, true);
                return;
            }
        }
        throw BeyondLimits(joints);
    }

    /// <summary>
    /// The refusal naming the first joint beyond its limits. A method of its own: the lambda's captured arrays would otherwise be
    /// allocated on every call of <see cref="RequireWithinLimits"/>, also when the joints are within (about 100 B per action).
    /// </summary>
    private TwinMotionException BeyondLimits(Joints joints)
    {
        double[] values = joints.ToArray(), min = Model.MinJoints.ToArray(), max = Model.MaxJoints.ToArray();
        int bad = Enumerable.Range(0, 6).First(i => values[i] < min[i] || values[i] > max[i]);
        return new TwinMotionException(FormattableString.Invariant(
            $"joint {bad + 1} target {values[bad]:0.###} deg is beyond its limits [{min[bad]:0.###}, {max[bad]:0.###}] deg"));
    }

    /// <summary>
    /// Moves to <paramref name="target"/> joints in <paramref name="seconds"/>, then traces the step at <paramref name="line"/>: at
    /// <paramref name="traced"/> joints when given (the waypoint of a motion that blends before it), none when <paramref name="trace"/> is false.
    /// A <paramref name="linear"/> motion keeps the tool on a straight line while it is part-way (when the arm interpolates), a
    /// motion with a <paramref name="path"/> (fraction of the way to joints: a blend) follows it, a circular one keeps the tool on its
    /// <paramref name="arc"/> (which ends at <paramref name="target"/>). False when a cleared path ended it early.
    /// </summary>
    public bool MoveTo(Joints target, double seconds, int line, string text, CancellationToken cancellation, Joints? traced = null, bool trace = true, bool linear = false,
        Func<double, Joints>? path = null, TwinArc? arc = null) =>
        MoveTo(target, seconds, line, text, cancellation, traced, trace, linear, new GivenPath(path), arc);

    /// <summary>
    /// <see cref="MoveTo(Joints, double, int, string, CancellationToken, Joints?, bool, bool, Func{double, Joints}?, TwinArc?)"/> with a path
    /// made only when a motion is part-way along it; <c>within</c>: the caller checked the target within the joint limits already
    /// (not looked at again).
    /// </summary>
    private bool MoveTo<TPath>(Joints target, double seconds, int line, string text, CancellationToken cancellation, Joints? traced, bool trace, bool linear,
        in TPath path, TwinArc? arc, bool within = false)
        where TPath : struct, ITwinPath
    {
        if (!within)
        {
            RequireWithinLimits(target);
        }
        if (Interpolates && Clock.RealTime && seconds > 0)
        {
            return MoveAlongPath(target, seconds, line, text, cancellation, traced, trace, linear, path, arc);
        }
        if (NextWake is not null && seconds > 0)
        {
            return MovePaced(target, seconds, line, text, cancellation, traced, trace, linear, path, arc);
        }
        return MoveInOneStep(target, seconds, line, text, cancellation, traced, trace);
    }

    /// <summary>A motion that is one step of program time: the time passes, then the arm is at <paramref name="target"/> (traced as <see cref="MoveTo"/> says).</summary>
    private bool MoveInOneStep(Joints target, double seconds, int line, string text, CancellationToken cancellation, Joints? traced, bool trace)
    {
        Clock.Wait(seconds, cancellation);
        if (!trace)
        {
            lock (_gate)
            {
                _joints = target;
            }
            return true;
        }
        // The trace's step is made before the arm is at the target (the joints it is at are the target's) and added with them in
        // one look at the gate, which keeps the flange pose of a forward solve too (FlangeAt kept it in a look of its own).
        Joints at = traced ?? target;
        Pose flange;
        bool known;
        lock (_gate)
        {
            known = KeptFlange(at, out flange);
        }
        if (!known)
        {
            flange = Model.Kinematics.Forward(at);
        }
        var entry = new TwinTraceEntry(line, TwinTraceKind.Motion, at, flange * ToolCenter, text, Clock.Seconds);
        lock (_gate)
        {
            if (!known)
            {
                KeepFlange(at, flange);
            }
            _joints = target;
            Add(entry);
        }
        return true;
    }

    /// <summary>Adds a step to the trace, with the arm's joints and TCP now (or those of <paramref name="at"/> joints).</summary>
    public void Record(int line, TwinTraceKind kind, string text, Joints? at = null)
    {
        (Joints joints, Pose tcp) = at is { } given ? (given, FlangeAt(given) * ToolCenter) : Now;
        var entry = new TwinTraceEntry(line, kind, joints, tcp, text, Clock.Seconds);
        lock (_gate)
        {
            Add(entry);
        }
    }

    /// <summary>Adds <paramref name="entry"/> to the trace (under the gate).</summary>
    private void Add(TwinTraceEntry entry)
    {
        _trace.Add(entry);
        if (MaxTrace > 0 && _trace.Count >= 2 * MaxTrace)
        {
            _trace.RemoveRange(0, _trace.Count - MaxTrace); // in batches: each entry is moved at most once per MaxTrace added
        }
    }
}
