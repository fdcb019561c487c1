namespace Machina;

internal sealed partial class RobotCursor
{
    private static readonly KinematicIssue[] NoIssues = [];

    /// <summary>The arm's model; when set, joints and pose are kept in step and every motion is checked. Null: no kinematics at all.</summary>
    internal RobotModel? Model;

    /// <summary>When true (and a model is set), a motion with any kinematic issue is refused instead of warned about.</summary>
    internal bool Strict;

    /// <summary>The kinematic issues found for the last applied motion (always empty without a model).</summary>
    internal IReadOnlyList<KinematicIssue> LastIssues = NoIssues;

    /// <summary>The joint values used as reference when a Cartesian target is solved and the previous joints are unknown: all zero.</summary>
    internal static readonly Joints ReferenceJoints = new(0, 0, 0, 0, 0, 0);

    /// <summary>True for the actions that move the robot (translations, rotations, transformations, joint moves, arcs).</summary>
    internal static bool IsMotion(RobotAction action) =>
        action is ActionTranslation or ActionRotation or ActionTransformation or ActionAxes or ActionArcMotion;

    /// <summary>The motion fields a motion action changes, saved so that a strict refusal can restore them.</summary>
    private readonly record struct MotionFields(
        Vector? Position, Vector? PrevPosition, Rotation? Rotation, Rotation? PrevRotation, Joints? Axes, Joints? PrevAxes,
        double? LastPathLength, Vector? ArcThrough, Rotation? ArcThroughRotation, double ExtrudedLength, double PrevExtrudedLength);

    private MotionFields SaveMotion() => new(Position, PrevPosition, Rotation, PrevRotation, Axes, PrevAxes,
        LastPathLength, ArcThrough, ArcThroughRotation, ExtrudedLength, PrevExtrudedLength);

    private void RestoreMotion(in MotionFields m)
    {
        Position = m.Position; PrevPosition = m.PrevPosition;
        Rotation = m.Rotation; PrevRotation = m.PrevRotation;
        Axes = m.Axes; PrevAxes = m.PrevAxes;
        LastPathLength = m.LastPathLength;
        ArcThrough = m.ArcThrough; ArcThroughRotation = m.ArcThroughRotation;
        ExtrudedLength = m.ExtrudedLength; PrevExtrudedLength = m.PrevExtrudedLength;
    }

    /// <summary>
    /// Applies a motion when a model is set: the plain motion first, then the missing half of the state (pose from joints or joints
    /// from pose) and the pre-flight checks. In strict mode any issue restores the saved fields and becomes the refusal.
    /// </summary>
    private string? ApplyWithModel(RobotAction action, RobotModel model) =>
        // Only a strict refusal restores the saved fields: a streamed move (not strict) neither copies nor zeroes the eleven
        // fields (about 400 bytes, three times per action: one per cursor), so the saving lives in a method of its own.
        Strict ? ApplyStrictWithModel(action, model) : ApplyAndCheck(action, model);

    private string? ApplyStrictWithModel(RobotAction action, RobotModel model)
    {
        MotionFields saved = SaveMotion();
        string? refusal = ApplyMotion(action);
        if (refusal is not null)
        {
            return refusal;
        }
        IReadOnlyList<KinematicIssue> issues = SyncOnce(model, action);
        if (issues.Count > 0)
        {
            RestoreMotion(saved);
            return "strict mode: " + string.Join(" ", issues.Select(i => i.ToString()));
        }
        LastIssues = issues;
        return null;
    }

    private string? ApplyAndCheck(RobotAction action, RobotModel model)
    {
        string? refusal = ApplyMotion(action);
        if (refusal is not null)
        {
            return refusal;
        }
        LastIssues = SyncOnce(model, action);
        return null;
    }

    private IReadOnlyList<KinematicIssue> SyncOnce(RobotModel model, RobotAction action) =>
        action is ActionAxes ? SyncFromJointsOnce(model, action) : SyncFromPoseOnce(model, action);

    private string? ApplyMotion(RobotAction action) => action switch
    {
        ActionTranslation a => ApplyTranslation(a),
        ActionRotation a => ApplyRotation(a),
        ActionTransformation a => ApplyTransformation(a),
        ActionAxes a => ApplyAxes(a),
        ActionArcMotion a => ApplyArc(a),
        _ => null,
    };

    /// <summary>
    /// How many motions this cursor solved itself (inverse kinematics for a Cartesian motion, forward kinematics and checks for a joint
    /// move) rather than reusing the solution another cursor of the robot found for the same action from the same state.
    /// </summary>
    internal int Solves { get; private set; }

    /// <summary>
    /// <see cref="SyncFromJoints"/>, reusing the pose and issues another cursor of the robot found for this joint move from the same
    /// state (the release and execution cursors apply what the issue cursor applied).
    /// </summary>
    private IReadOnlyList<KinematicIssue> SyncFromJointsOnce(RobotModel model, RobotAction action)
    {
        var key = new PoseSolveKey(model, PrevAxes, default, default, Tool, null, null, MotionType, Speed, Axes);
        if (Volatile.Read(ref action.Solved) is SolvedPose solved && solved.Key == key)
        {
            Position = solved.Tcp.Position;
            Rotation = solved.Tcp.Rotation;
            return solved.Issues;
        }
        Solves++;
        IReadOnlyList<KinematicIssue> issues = Kept(SyncFromJoints(model));
        Volatile.Write(ref action.Solved, new SolvedPose(key, null, issues) { Tcp = new Pose(Position!.Value, Rotation!.Value) });
        return issues;
    }

    /// <summary>The issues as a solution keeps them: most motions have none, and each waiting action kept an empty list of its own.</summary>
    private static IReadOnlyList<KinematicIssue> Kept(IReadOnlyList<KinematicIssue> issues) => issues.Count == 0 ? NoIssues : issues;

    /// <summary>After AxesTo/Axes: the pose is the forward kinematics of the joints with the attached tool applied.</summary>
    private IReadOnlyList<KinematicIssue> SyncFromJoints(RobotModel model)
    {
        Joints target = Axes!.Value;
        IReadOnlyList<KinematicIssue> issues = KinematicChecks.Check(model, PrevAxes, target, KinematicMotion.Joint, Speed);
        Pose tcp = TcpOf(model.Kinematics.Forward(target));
        Position = tcp.Position;
        Rotation = tcp.Rotation;
        return issues;
    }

    /// <summary>
    /// <see cref="SyncFromPose"/>, reusing the solution another cursor of the robot found for this action from the same state (the
    /// release and execution cursors apply what the issue cursor applied): following a line solves the arm many times.
    /// </summary>
    private IReadOnlyList<KinematicIssue> SyncFromPoseOnce(RobotModel model, RobotAction action)
    {
        bool arc = action is ActionArcMotion;
        var key = new PoseSolveKey(model, PrevAxes, Position!.Value, Rotation!.Value, Tool, arc ? ArcThrough : null, arc ? ArcThroughRotation : null,
            MotionType, Speed);
        if (Volatile.Read(ref action.Solved) is SolvedPose solved && solved.Key == key)
        {
            Axes = solved.Axes;
            return solved.Issues;
        }
        Solves++;
        IReadOnlyList<KinematicIssue> issues = Kept(SyncFromPose(model, action));
        Volatile.Write(ref action.Solved, new SolvedPose(key, Axes, issues));
        return issues;
    }

    /// <summary>
    /// After a Cartesian motion: the joints are the inverse kinematics of the flange pose (TCP pose × tool⁻¹): for lines and arcs the
    /// joints reached by following the path from the previous joints, for joint moves the solution closest to them (or to all-zero
    /// joints when they are unknown). Unreachable: the pose is kept and the joints become unknown.
    /// </summary>
    private IReadOnlyList<KinematicIssue> SyncFromPose(RobotModel model, RobotAction action)
    {
        Pose flange = FlangePose(Position!.Value, Rotation!.Value);
        Vector? through = action is ActionArcMotion ? ArcThrough : null;
        bool linear = action is not ActionArcMotion && MotionType == MotionType.Linear;
        Pose tool = Tool is null ? Pose.Identity : new Pose(Tool.TcpPosition, Tool.TcpOrientation);
        // Lines and arcs are followed from the previous joints, so the joints kept are those the arm arrives with along the path.
        IReadOnlyList<KinematicIssue> issues = KinematicChecks.Check(model, PrevAxes, flange, linear ? KinematicMotion.Linear : KinematicMotion.Joint, Speed, tool, out Joints? solution, through);
        if (through is Vector via && PrevAxes is null)
        {
            // Without previous joints the arc cannot be followed: at least check its through point.
            IReadOnlyList<KinematicIssue> viaIssues = KinematicChecks.Check(model, null, FlangePose(via, ArcThroughRotation ?? Rotation!.Value), KinematicMotion.Joint, Speed, tool, out _);
            if (viaIssues.Count > 0)
            {
                issues = [.. issues, .. viaIssues.Select(i => i with { Reason = "through point: " + i.Reason })];
            }
        }
        // With known previous joints the checks already solved for the followed or closest solution; otherwise take the one closest to all-zero joints.
        Axes = PrevAxes is null ? model.Kinematics.Closest(flange, ReferenceJoints) : solution;
        return issues;
    }

    /// <summary>The TCP pose for a flange pose, with the attached tool (if any).</summary>
    private Pose TcpOf(Pose flange) =>
        Tool is null ? flange : new Pose(flange.Position + flange.Rotation * Tool.TcpPosition, flange.Rotation * Tool.TcpOrientation);

    /// <summary>The flange pose for a TCP pose, with the attached tool (if any).</summary>
    internal Pose FlangePose(Vector tcpPosition, Rotation tcpRotation)
    {
        if (Tool is null)
        {
            return new Pose(tcpPosition, tcpRotation);
        }
        (Vector p, Rotation r) = FlangeOf(tcpPosition, tcpRotation, Tool);
        return new Pose(p, r);
    }
}
