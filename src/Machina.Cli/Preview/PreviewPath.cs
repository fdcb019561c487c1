using Machina.Cli.Commands;
using Machina.Cli.Programs;

namespace Machina.Cli.Preview;

/// <summary>How a stretch of the tool path was programmed, which decides its colour.</summary>
internal enum SegmentKind
{
    /// <summary>A straight-line move (MoveL, LIN, movel).</summary>
    Linear,

    /// <summary>A joint move: the real path is a curve; drawn straight (approximate).</summary>
    Joint,

    /// <summary>A circular arc through a point.</summary>
    Arc,

    /// <summary>A 3D printer moving without extruding.</summary>
    Travel,

    /// <summary>A move while extruding material.</summary>
    Extrusion,
}

/// <summary>One motion: its kind, the program line, and its points from where it starts to its target (arcs: sampled along the circle).</summary>
internal sealed record PathSegment(SegmentKind Kind, int Line, IReadOnlyList<Vector> Points);

/// <summary>A problem to draw where it happens (<paramref name="At"/>, null when the position is not known yet): a kinematic issue or an instruction that could not be applied.</summary>
internal sealed record PathWarning(Vector? At, int Line, int Column, string Instruction, string Message);

/// <summary>The arm drawn at one moment of the program (<paramref name="Label"/>: start, end or a warning's line): its joints from base to flange.</summary>
internal sealed record ArmPose(string Label, IReadOnlyList<Vector> Points);

/// <summary>The tool path of a program, as the robot's state follows it: what <c>machina preview</c> draws.</summary>
internal sealed class PreviewPath
{
    /// <summary>Points per arc drawn.</summary>
    internal const int ArcSamples = 48;

    /// <summary>Every motion that moved the tool tip, in order.</summary>
    internal List<PathSegment> Segments { get; } = [];

    /// <summary>The targets in order: the first known position, then every motion's end (what the test compares with the program).</summary>
    internal List<Vector> Targets { get; } = [];

    /// <summary>Problems, where they occur.</summary>
    internal List<PathWarning> Warnings { get; } = [];

    /// <summary>The arm at the start, at the end and where the first warnings with known joints are (with a model only).</summary>
    internal List<ArmPose> Arms { get; } = [];

    /// <summary>Where the model's flange can get (with a model only), drawn as an outline in each view; not part of the framing.</summary>
    internal ReachEnvelope? Reach { get; private set; }

    /// <summary>Most arms drawn where a warning is.</summary>
    internal const int MaxWarningArms = 2;

    /// <summary>Where the tool path starts, or null when no position is ever known.</summary>
    internal Vector? Start => Targets.Count > 0 ? Targets[0] : null;

    /// <summary>Where the tool path ends.</summary>
    internal Vector? End => Targets.Count > 0 ? Targets[^1] : null;

    /// <summary>The program's estimated cycle time on the model's brand of controller (or a generic one).</summary>
    internal CycleTime CycleTime { get; } = new();

    /// <summary>Actions read.</summary>
    internal int Actions { get; private set; }

    /// <summary>
    /// Follows the program from <paramref name="reader"/> with the arm <paramref name="model"/> (or none). Moves of a 3D printer
    /// (<paramref name="printer"/>) and moves while extruding are travel or extrusion. Instructions that cannot be applied become warnings.
    /// </summary>
    internal static PreviewPath Build(ProgramReader reader, RobotModel? model, bool printer, CancellationToken cancellationToken)
    {
        var path = new PreviewPath { JointsFollowTheArm = model is not null, Reach = model is null ? null : ReachEnvelope.Of(model) };
        var trial = new ProgramTrial(model);
        var problems = new List<string>();
        Vector? last = null;
        Joints? firstJoints = null, lastJoints = null;
        var warningArms = new List<ArmPose>();
        foreach (InstructionStatement statement in reader.Read(cancellationToken))
        {
            path.Actions++;
            TrialStep step = trial.Try(statement.Action);
            path.CycleTime.Add(step);
            CheckCommand.Problems(step, problems);
            if (step.Refusal is string refusal)
            {
                path.Warnings.Add(new PathWarning(last, statement.Line, statement.Column, statement.Action.ToInstruction(), "not applied: " + refusal));
                continue;
            }
            Vector? now = trial.Position;
            if (step.IsMotion && now is Vector target)
            {
                if (last is Vector from)
                {
                    if (from != target || statement.Action is ActionArcMotion)
                    {
                        SegmentKind kind = KindOf(statement.Action, trial, printer);
                        IReadOnlyList<Vector> points = statement.Action is ActionArcMotion && trial.ArcThrough is Vector through
                            ? ArcPoints(from, through, target)
                            : kind == SegmentKind.Joint && model is not null && trial.PreviousAxes is Joints a && trial.Axes is Joints b
                                ? JointPoints(model, trial.Tool, a, b, from, target)
                                : [from, target];
                        path.Segments.Add(new PathSegment(kind, statement.Line, points));
                        path.Targets.Add(target);
                    }
                }
                else
                {
                    path.Targets.Add(target);
                }
            }
            last = now ?? last;
            if (model is not null && step.IsMotion && trial.Axes is Joints joints)
            {
                firstJoints ??= joints;
                lastJoints = joints;
                if (problems.Count > 0 && warningArms.Count < MaxWarningArms)
                {
                    warningArms.Add(new ArmPose($"!{statement.Line}", model.LinkPositions(joints)));
                }
            }
            foreach (string problem in problems)
            {
                path.Warnings.Add(new PathWarning(now ?? last, statement.Line, statement.Column, statement.Action.ToInstruction(), problem));
            }
        }
        if (model is not null && firstJoints is Joints first)
        {
            path.Arms.Add(new ArmPose("start", model.LinkPositions(first)));
            path.Arms.AddRange(warningArms);
            if (lastJoints is Joints end && end != first)
            {
                path.Arms.Add(new ArmPose("end", model.LinkPositions(end)));
            }
        }
        return path;
    }

    private static SegmentKind KindOf(RobotAction action, ProgramTrial trial, bool printer)
    {
        if (trial.IsExtruding)
        {
            return SegmentKind.Extrusion;
        }
        if (printer)
        {
            return SegmentKind.Travel;
        }
        return action switch
        {
            ActionArcMotion => SegmentKind.Arc,
            ActionAxes => SegmentKind.Joint,
            _ => trial.MotionType == MotionType.Joint ? SegmentKind.Joint : SegmentKind.Linear,
        };
    }

    /// <summary>Points per joint move drawn with a model.</summary>
    internal const int JointSamples = 24;

    /// <summary>
    /// Where the tool tip goes during a joint move from joints <paramref name="a"/> to <paramref name="b"/>: the joints turn together
    /// (interpolated linearly), and each step's tip is the forward kinematics with the tool. The ends are the exact targets.
    /// </summary>
    internal static IReadOnlyList<Vector> JointPoints(RobotModel model, Tool? tool, Joints a, Joints b, Vector from, Vector to)
    {
        var points = new List<Vector>(JointSamples + 1) { from };
        for (int i = 1; i < JointSamples; i++)
        {
            double t = (double)i / JointSamples;
            Pose flange = model.Kinematics.Forward(new Joints(
                a.J1 + ((b.J1 - a.J1) * t), a.J2 + ((b.J2 - a.J2) * t), a.J3 + ((b.J3 - a.J3) * t),
                a.J4 + ((b.J4 - a.J4) * t), a.J5 + ((b.J5 - a.J5) * t), a.J6 + ((b.J6 - a.J6) * t)));
            points.Add(tool is null ? flange.Position : flange.Position + flange.Rotation.Rotate(tool.TcpPosition));
        }
        points.Add(to);
        return points;
    }

    /// <summary>True when joint moves follow the arm's joints (a model was given), false when they are drawn straight.</summary>
    internal bool JointsFollowTheArm { get; private set; }

    /// <summary>Points along the circle from <paramref name="start"/> through <paramref name="through"/> to <paramref name="end"/>, both ends exact.</summary>
    internal static IReadOnlyList<Vector> ArcPoints(Vector start, Vector through, Vector end)
    {
        Vector a = through - start, b = end - start;
        Vector normal = Vector.Cross(a, b);
        double n2 = normal.SquaredLength;
        if (n2 < 1e-12)
        {
            return [start, through, end];
        }
        Vector center = start + (Vector.Cross((b * a.SquaredLength) - (a * b.SquaredLength), normal) * (1 / (2 * n2)));
        Vector u = start - center;
        double radius = u.Length;
        Vector axisX = u * (1 / radius);
        Vector axisY = Vector.Cross(normal * (1 / Math.Sqrt(n2)), axisX);
        double Angle(Vector p)
        {
            Vector d = p - center;
            double angle = Math.Atan2(Vector.Dot(d, axisY), Vector.Dot(d, axisX));
            return angle < 0 ? angle + (2 * Math.PI) : angle;
        }
        double sweep = Angle(end);
        if (Angle(through) > sweep)
        {
            sweep -= 2 * Math.PI;
        }
        var points = new List<Vector>(ArcSamples + 1) { start };
        for (int i = 1; i < ArcSamples; i++)
        {
            double t = sweep * i / ArcSamples;
            points.Add(center + (axisX * (radius * Math.Cos(t))) + (axisY * (radius * Math.Sin(t))));
        }
        points.Add(end);
        return points;
    }

    /// <summary>The smallest and largest coordinates of everything drawn, or null when nothing is.</summary>
    internal (Vector Min, Vector Max)? Bounds()
    {
        IEnumerable<Vector> all = Segments.SelectMany(s => s.Points).Concat(Targets).Concat(Warnings.Where(w => w.At is not null).Select(w => w.At!.Value))
            .Concat(Arms.SelectMany(a => a.Points));
        if (!all.Any())
        {
            return null;
        }
        return (new Vector(all.Min(p => p.X), all.Min(p => p.Y), all.Min(p => p.Z)), new Vector(all.Max(p => p.X), all.Max(p => p.Y), all.Max(p => p.Z)));
    }
}
