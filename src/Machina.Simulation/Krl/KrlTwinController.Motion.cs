using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// Motion on the twin arm: PTP, LIN and CIRC to axis or Cartesian targets in $BASE with $TOOL, software limit switches
/// ($SOFTN_END/$SOFTP_END) checked before the motion starts, motion time from $VEL/$ACC (paths) and $VEL_AXIS/$ACC_AXIS (axes), and
/// approximate positioning between LIN motions in a program without EthernetKRL channels (docs/simulation.md).
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>How the trace marks the first motion of a run, the BCO run that brings the robot onto the program's path.</summary>
    public const string BcoRun = "(BCO run)";

    private static readonly string[] AxisNames = ["A1", "A2", "A3", "A4", "A5", "A6"];
    private int _coincident;
    private CancellationToken _motionCancellation;

    /// <summary>Joints of an AXIS or E6AXIS value.</summary>
    public static Joints JointsOf(KrlStructValue axes)
    {
        int[] indexes = axes.Type.AxisIndexes;
        return new(Axis(0), Axis(1), Axis(2), Axis(3), Axis(4), Axis(5));

        double Axis(int i) => indexes[i] >= 0 ? axes.Real(indexes[i]) : 0;
    }

    /// <summary>An E6AXIS value of <paramref name="joints"/>.</summary>
    public static KrlStructValue AxesValue(Joints joints)
    {
        var value = (KrlStructValue)KrlValues.Default(KrlTypes.E6Axis);
        for (int i = 0; i < 6; i++)
        {
            value.SetReal(i, joints[i]);
        }
        return value;
    }

    /// <summary>$AXIS_ACT: the axes now.</summary>
    public object AxesNow() => AxesValue(Arm.Joints);

    /// <summary>$POS_ACT: the TCP now in $BASE, with S and T of the axes.</summary>
    public object PositionNow()
    {
        (Joints joints, Pose tcp) = Arm.Now;
        return PositionOf(tcp, joints);
    }

    /// <summary>An E6POS of the TCP at <paramref name="tcp"/> (base frame of the robot) in $BASE, with S and T of <paramref name="joints"/>.</summary>
    private KrlStructValue PositionOf(Pose tcp, Joints joints) => PositionOf(tcp, joints, KeptBase());

    /// <summary><see cref="PositionOf(Pose, Joints)"/> in the base frame <paramref name="baseFrame"/>.</summary>
    private KrlStructValue PositionOf(Pose tcp, Joints joints, KeptFrame baseFrame)
    {
        Span<double> c = stackalloc double[6];
        PositionComponents(tcp, baseFrame, c);
        KukaConfiguration configuration = KukaConfiguration.From(Options.Model, joints);
        var value = (KrlStructValue)KrlValues.Default(KrlTypes.E6Pos);
        for (int i = 0; i < 6; i++)
        {
            value.SetReal(i, c[i]);
        }
        value[6] = KrlValues.Box(configuration.Status);
        value[7] = KrlValues.Box(configuration.Turn);
        return value;
    }

    /// <summary>X, Y, Z, A, B and C of the TCP at <paramref name="tcp"/> (base frame of the robot) in <paramref name="baseFrame"/>: an E6POS's six REALs, unboxed.</summary>
    private static void PositionComponents(Pose tcp, KeptFrame baseFrame, Span<double> components)
    {
        Pose pose = baseFrame.Inverse * tcp;
        YawPitchRoll abc = pose.Rotation.ToYawPitchRoll();
        (components[0], components[1], components[2], components[3], components[4], components[5]) =
            (pose.Position.X, pose.Position.Y, pose.Position.Z, abc.Yaw, abc.Pitch, abc.Roll);
    }

    /// <summary>BAS(#INITMOV): axis speeds and accelerations 100 %, path speed and acceleration to the defaults.</summary>
    public void InitialiseMotion()
    {
        foreach (string name in new[] { "$VEL_AXIS", "$ACC_AXIS" })
        {
            object[] items = ((KrlArrayValue)Environment.System[name].Value).Objects;
            Array.Fill(items, 100);
        }
        ((KrlStructValue)Motion.Vel.Value).Values[0] = Options.DefaultCpVelocity;
        ((KrlStructValue)Motion.Acc.Value).Values[0] = Options.DefaultCpAcceleration;
    }

    /// <summary>$ADVANCE was written: KRL allows 0 to 5.</summary>
    public void AdvanceChanged()
    {
        if ((int)Motion.Advance.Value is < 0 or > 5)
        {
            throw new KrlRuntimeException("Value assignment inadmissible: $ADVANCE takes 0 to 5");
        }
    }

    /// <summary>$TOOL was written: the arm's TCP follows it (the advance run ends: the arm stops at its last point first).</summary>
    public void ToolChanged()
    {
        Arm.FinishBlend(_motionCancellation);
        Arm.ToolCenter = KeptTool().Pose;
        Arm.Record(TraceLine(), TwinTraceKind.Tool, "$TOOL = " + KrlValues.Format(Motion.Tool.Value));
    }

    /// <summary>
    /// The axes that put the TCP at <paramref name="position"/> (in $BASE with $TOOL), nearest to <paramref name="near"/>; with
    /// <paramref name="useStatusTurn"/> only those of the position's S and T. Null when none is within the software limit switches.
    /// </summary>
    public Joints? Solve(KrlStructValue position, Joints near, bool useStatusTurn, out string why)
    {
        KeptFrame baseFrame = KeptBase(), tool = KeptTool();
        Span<double> target = stackalloc double[6];
        PoseComponents(position, target);
        return Solve(baseFrame, tool, target, near, useStatusTurn ? position : null, out _, out _, out why);
    }

    /// <summary>
    /// The axes that put the TCP at the six components <paramref name="target"/> (in <paramref name="baseFrame"/> with
    /// <paramref name="tool"/>), nearest to <paramref name="near"/>; with a <paramref name="statusTurn"/> position only those of its S
    /// and T. <paramref name="to"/> is the target's pose in $BASE, <paramref name="goal"/> in the robot's base frame (kept with the
    /// answer: the motion after the driver's INVERSE uses them again).
    /// </summary>
    private Joints? Solve(KeptFrame baseFrame, KeptFrame tool, ReadOnlySpan<double> target, Joints near, KrlStructValue? statusTurn, out Pose to, out Pose goal,
        out string why)
    {
        IKinematics kinematics = Options.Model.Kinematics;
        if (statusTurn is null && KeptFor(kinematics, baseFrame, tool, target, near) is { } kept)
        {
            (to, goal, why) = (kept.To, kept.Goal, kept.Why);
            return kept.Solution;
        }
        to = PoseOf(target);
        goal = baseFrame.Pose * to;
        Pose flange = goal * tool.Inverse;
        why = "";
        if (statusTurn is not null)
        {
            return SolveWithStatusTurn(statusTurn, flange, near, out why);
        }
        Joints? solution = kinematics.Closest(flange, near);
        if (solution is null)
        {
            why = kinematics.WhyNoSolution(flange) is { Kind: KinematicIssueKind.JointLimit } issue
                ? $"the axis position that reaches it is beyond the software limit switches ({issue})"
                : "it is outside the robot's workspace";
        }
        _keptSolution = new KeptSolution(kinematics, baseFrame, tool, target, near, solution, why, to, goal);
        return solution;
    }

    /// <summary>
    /// The axes of the position's S and T that put the flange at <paramref name="flange"/>, nearest to <paramref name="near"/> (a
    /// method of its own: its lambdas' closure was made at every solve, two an action).
    /// </summary>
    private Joints? SolveWithStatusTurn(KrlStructValue position, Pose flange, Joints near, out string why)
    {
        IKinematics kinematics = Options.Model.Kinematics;
        var wanted = new KukaConfiguration((int)position.Values[6], (int)position.Values[7]);
        Joints? best = kinematics.InverseAllTurns(flange)
            .Where(j => Options.Model.IsWithinLimits(j) && KukaConfiguration.From(Options.Model, j) == wanted)
            .Select(j => (Joints?)j)
            .MinBy(j => (j!.Value - near).NormSq());
        if (best is not null)
        {
            why = "";
            return best;
        }
        why = $"no axis position with S {wanted.StatusText} and T {wanted.TurnText} within the software limit switches reaches it";
        return null;
    }

    /// <summary>
    /// Runs a motion statement: checks the target before the motion starts, then moves the arm and traces the end. A LIN with an
    /// approximation (C_DIS, C_VEL, C_ORI) and $ADVANCE of 1 or more returns as the arm enters its approximation zone, and the next
    /// LIN rounds the corner (<see cref="TwinArm.MoveLinear"/>); PTP and CIRC stop exactly, after the arm finished a pending corner.
    /// </summary>
    public void Move(string kind, object target, object? auxiliary, string? approximation, int line, CancellationToken cancellation)
    {
        _motionCancellation = cancellation;
        if (kind != "LIN")
        {
            Arm.FinishBlend(cancellation);
        }
        TwinBlend? blend;
        Joints start;
        Joints end;
        double pathMm = 0, turnDegrees = 0;
        Pose? goal = null;
        TwinArc? arc = null;
        if (IsAxes(target))
        {
            blend = Arm.PendingBlend;
            start = blend?.CornerJoints ?? Arm.Joints;
            end = JointsOf(ToStruct(target, AxesValue(start), KrlTypes.E6Axis, axesOnly: true)!);
            RequireSoftLimits(end);
        }
        else
        {
            // The pending corner, or the joints and the TCP now, in one look at the arm.
            blend = Arm.PendingBlendOrNow(out Joints here, out Pose tcp);
            start = blend?.CornerJoints ?? here;
            Pose corner = blend?.Corner ?? tcp;
            KeptFrame baseFrame = KeptBase(), tool = KeptTool();
            bool statusTurn = kind == "PTP" && Given(target, "S") && Given(target, "T");
            // The start and the target as X, Y, Z, A, B and C in $BASE. A target of a Cartesian type that gives only these (a FRAME,
            // a POS or E6POS written whole, or an aggregate of them) takes the rest from the start: no E6POS of the start and no copy
            // of it are made, the six REALs are the ones they would hold. S and T (a PTP's), a CIRC's auxiliary point or another type
            // go through the E6POS.
            Span<double> here6 = stackalloc double[6], there6 = stackalloc double[6];
            KrlStructValue? current = null, position = null;
            if (statusTurn || kind == "CIRC" || !TargetPose(target, here6, corner, baseFrame, there6))
            {
                current = PositionOf(corner, start, baseFrame);
                position = ToStruct(target, current, KrlTypes.E6Pos, axesOnly: false)!;
                PoseComponents(current, here6);
                PoseComponents(position, there6);
            }
            end = Solve(baseFrame, tool, there6, start, statusTurn ? position : null, out Pose to, out Pose toGoal, out string why)
                ?? throw new KrlRuntimeException($"Target not reachable: {kind} {DescribeXyz(there6)}: {why}");
            RequireSoftLimits(end);
            Pose from = PoseOf(here6);
            goal = toGoal;
            pathMm = (to.Position - from.Position).Length;
            turnDegrees = TwinRotation.AngleDegrees(from.Rotation, to.Rotation);
            if (kind == "CIRC" && auxiliary is not null)
            {
                // The circle through the start, the auxiliary point and the end, in the robot's base frame; the tool turns evenly
                // from the start to the end orientation in space ($ORI_TYPE #VAR, $CIRC_TYPE #BASE; the auxiliary point's is not used).
                Pose via = PoseOf(ToStruct(auxiliary, current!, KrlTypes.E6Pos, axesOnly: false)!);
                Pose frame = baseFrame.Pose;
                arc = TwinArc.Through(frame * from, (frame * via).Position, frame * to, TwinArcOrientation.Even) ?? throw new KrlRuntimeException(string.Create(CultureInfo.InvariantCulture,
                    $"Circle not possible: CIRC: the start, auxiliary and end points do not define a circle {TwinArc.NotACircle}"));
                pathMm = arc.LengthMm;
            }
        }
        double seconds = kind == "PTP" ? AxisSeconds(start, end) : PathSeconds(pathMm, turnDegrees);
        // Only the first motion of a run looks with a locked exchange (a locked instruction at every motion before).
        bool bco = Volatile.Read(ref _coincident) == 0 && Interlocked.Exchange(ref _coincident, 1) == 0;
        string text = bco ? kind + (approximation is null ? "" : " " + approximation) + " " + BcoRun : MotionText(kind, approximation);
        if (kind == "LIN" && goal is { } tcpGoal && !bco)
        {
            (double v, double acceleration) = PathSpeed();
            double zone = ApproximationMm(approximation, pathMm, turnDegrees, v, acceleration);
            bool mayBlend = zone > 0 && (int)Motion.Advance.Value >= 1 && !HasExternalInputs;
            Arm.MoveLinear(new TwinLinearMove(tcpGoal, end, v, acceleration, seconds, zone, mayBlend), line, text, cancellation);
            return;
        }
        Arm.FinishBlend(cancellation);
        Arm.MoveTo(end, seconds, line, text, cancellation, linear: kind == "LIN", arc: arc);
    }

    /// <summary>
    /// The target's X, Y, Z, A, B and C into <paramref name="there"/>, those it does not give from the TCP at <paramref name="tcp"/>
    /// (in <paramref name="baseFrame"/>, into <paramref name="here"/>), as the E6POS the target converts to would hold them; false
    /// (nothing read) unless the target is a FRAME, POS or E6POS, or an aggregate of one that gives no other component (a given S,
    /// T or external axis is converted, and checked, as the E6POS's).
    /// </summary>
    private static bool TargetPose(object target, Span<double> here, Pose tcp, KeptFrame baseFrame, Span<double> there)
    {
        switch (target)
        {
            case KrlStructValue whole when KrlTypes.IsCartesian(whole.Type):
            {
                PositionComponents(tcp, baseFrame, here);
                PoseComponents(whole, there); // X to C are the first six components of all three, all given
                return true;
            }
            case KrlPartialValue part when KrlTypes.IsCartesian(part.Type):
            {
                int[] given = part.Indexes;
                for (int i = 0; i < given.Length; i++)
                {
                    if ((uint)given[i] >= 6)
                    {
                        return false;
                    }
                }
                PositionComponents(tcp, baseFrame, here);
                here.CopyTo(there);
                for (int i = 0; i < given.Length; i++)
                {
                    there[given[i]] = KrlValues.ToReal(part.Values[i]);
                }
                return true;
            }
            default:
                return false;
        }
    }

    /// <summary>The trace's text of each motion keyword and approximation met (a handful per program: made once, not per motion).</summary>
    private readonly Dictionary<(string Kind, string? Approximation), string> _motionTexts = [];

    /// <summary>The last text given, with its keyword and approximation (the same strings of the same statement: no look-up, which hashed both).</summary>
    private MotionTextKept? _lastMotionText;

    private sealed record MotionTextKept(string Kind, string? Approximation, string Text);

    private string MotionText(string kind, string? approximation)
    {
        if (_lastMotionText is { } last && ReferenceEquals(last.Kind, kind) && ReferenceEquals(last.Approximation, approximation))
        {
            return last.Text;
        }
        if (!_motionTexts.TryGetValue((kind, approximation), out string? text))
        {
            text = approximation is null ? kind : kind + " " + approximation;
            _motionTexts[(kind, approximation)] = text;
        }
        _lastMotionText = new MotionTextKept(kind, approximation, text);
        return text;
    }

    /// <summary>$VEL.CP (m/s) and $ACC.CP (m/s²).</summary>
    private (double Speed, double Acceleration) PathSpeed()
    {
        var vel = (KrlStructValue)Motion.Vel.Value;
        var acc = (KrlStructValue)Motion.Acc.Value;
        return (vel.Real(0), Math.Max(acc.Real(0), 1e-6));
    }

    /// <summary>
    /// How far before its end point a LIN starts to approximate, in mm (none: exact stop): C_DIS at $APO.CDIS; C_VEL where the
    /// braking speed falls below $APO.CVEL % of $VEL.CP; C_ORI where the turn left falls below $APO.CORI (the whole way, up to the
    /// half the blend allows, when the tool does not turn). The twin rounds the corner in the same shape for all three.
    /// </summary>
    private double ApproximationMm(string? approximation, double pathMm, double turnDegrees, double speed, double acceleration)
    {
        var apo = (KrlStructValue)Motion.Apo.Value;
        double mm = approximation?.ToUpperInvariant() switch
        {
            "C_DIS" => apo.Real(2),
            "C_VEL" => Math.Pow(speed * Math.Clamp(apo.Real(0), 0, 100) / 100, 2) / (2 * acceleration) * 1000,
            "C_ORI" => turnDegrees > 0 ? pathMm * Math.Min(1, apo.Real(3) / turnDegrees) : pathMm,
            _ => 0,
        };
        return mm > 0 ? mm : 0;
    }

    private static bool Given(object target, string field) => target switch
    {
        KrlPartialValue p => p.Indexes.Any(i => string.Equals(p.Type.Fields[i].Name, field, StringComparison.OrdinalIgnoreCase)),
        KrlStructValue s => s.Type.FieldIndex(field) >= 0,
        _ => false,
    };

    /// <summary>True when <paramref name="target"/> is an AXIS or E6AXIS (or an aggregate of one).</summary>
    private static bool IsAxes(object target) => KrlTypes.IsAxes(target is KrlPartialValue p ? p.Type : ((KrlStructValue)target).Type);

    /// <summary>The target as <paramref name="type"/>, the components it leaves out from <paramref name="current"/>; null when it is not of that family.</summary>
    private static KrlStructValue? ToStruct(object target, KrlStructValue current, KrlType type, bool axesOnly)
    {
        KrlType actual = target is KrlPartialValue p ? p.Type : ((KrlStructValue)target).Type;
        if (axesOnly != KrlTypes.IsAxes(actual))
        {
            return null;
        }
        return (KrlStructValue)KrlConvert.To(type, target, current);
    }

    private void RequireSoftLimits(Joints joints)
    {
        var min = (KrlArrayValue)Motion.SoftMin.Value;
        var max = (KrlArrayValue)Motion.SoftMax.Value;
        for (int i = 0; i < 6; i++)
        {
            if (joints[i] < min.Real(i) - 1e-9 || joints[i] > max.Real(i) + 1e-9)
            {
                bool below = joints[i] < min.Real(i);
                throw new KrlRuntimeException(string.Create(CultureInfo.InvariantCulture,
                    $"Software limit switch {AxisNames[i]} {(below ? "-" : "+")}: the target {joints[i]:0.###} deg is beyond {(below ? min.Real(i) : max.Real(i)):0.###} deg"));
            }
        }
    }

    private static string DescribeXyz(ReadOnlySpan<double> p) => string.Create(CultureInfo.InvariantCulture,
        $"{{X {p[0]:0.###}, Y {p[1]:0.###}, Z {p[2]:0.###}, A {p[3]:0.###}, B {p[4]:0.###}, C {p[5]:0.###}}}");

    /// <summary>PTP time: the slowest axis at $VEL_AXIS % of its speed, ramping at $ACC_AXIS %.</summary>
    private double AxisSeconds(Joints from, Joints to)
    {
        object[] vel = ((KrlArrayValue)Motion.VelAxis.Value).Objects;
        object[] acc = ((KrlArrayValue)Motion.AccAxis.Value).Objects;
        double seconds = 0;
        for (int i = 0; i < 6; i++)
        {
            double full = Options.Model.MaxJointSpeeds is { } speeds ? speeds[i] : Options.DefaultAxisSpeed;
            double speed = full * Math.Clamp((int)vel[i], 1, 100) / 100.0;
            double acceleration = full / Options.AxisRampSeconds * Math.Clamp((int)acc[i], 1, 100) / 100.0;
            seconds = Math.Max(seconds, TwinMotion.TrapezoidSeconds(Math.Abs(to[i] - from[i]), speed, acceleration));
        }
        return seconds;
    }

    /// <summary>LIN and CIRC time: the path at $VEL.CP with $ACC.CP, or the turn at $VEL.ORI1 with $ACC.ORI1 if slower.</summary>
    private double PathSeconds(double mm, double degrees)
    {
        var vel = (KrlStructValue)Motion.Vel.Value;
        var acc = (KrlStructValue)Motion.Acc.Value;
        double cp = vel.Real(0);
        if (!(cp > 0) && mm > 0)
        {
            throw new KrlRuntimeException("Programmed path velocity $VEL.CP is 0: the motion would never end");
        }
        double path = mm > 0 ? TwinMotion.TrapezoidSeconds(mm / 1000, cp, Math.Max(acc.Real(0), 1e-6)) : 0;
        double turn = TwinMotion.TrapezoidSeconds(degrees, Math.Max(vel.Real(1), 1e-6), Math.Max(acc.Real(1), 1e-6));
        return Math.Max(path, turn);
    }

    /// <summary>
    /// The advance run ends (WAIT FOR, the end of the program): the arm finishes a pending corner and stops at its point. The
    /// submit interpreter has no advance run of the arm: its waits leave the robot program's motion alone.
    /// </summary>
    public void EndAdvanceRun(CancellationToken cancellation)
    {
        if (!OnSubmitInterpreter)
        {
            Arm.FinishBlend(cancellation);
        }
    }

    /// <summary>
    /// WAIT SEC: the program waits (the twin's advance run ends here, as on the controller: the arm stops at its last point first).
    /// In the submit interpreter it holds that interpreter only, on the wall clock its cycle runs on: no step of the arm's trace,
    /// no program time of the robot's.
    /// </summary>
    public void WaitSeconds(double seconds, int line, CancellationToken cancellation)
    {
        if (OnSubmitInterpreter)
        {
            cancellation.ThrowIfCancellationRequested();
            if (seconds > 0)
            {
                Clock.WaitWall(seconds, cancellation);
            }
            return;
        }
        Arm.FinishBlend(cancellation);
        Clock.Wait(seconds, cancellation);
        Arm.Record(line, TwinTraceKind.Wait, FormattableString.Invariant($"WAIT SEC {seconds}"));
    }
}
