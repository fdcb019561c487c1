using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Fixed-position events (RAPID reference: TriggIO, TriggEquip, TriggInt, TriggCheckIO, TriggSpeed, TriggL, TriggJ, TriggC): the first
/// five define an event in a <c>triggdata</c>, a TriggL, TriggJ or TriggC fires its events (\T2 … \T8 besides Trigg_1) where the TCP
/// passes their point of the path (along the circle for TriggC): Distance mm before the end point, from the start point with \Start, or Distance seconds before the end point with
/// \Time; \DODelay sets the output that much later, TriggEquip's EquipLag that much earlier. The move runs in pieces that end at
/// the events, timed as the whole move, so without real time an event's output is traced at its point of the path and its program
/// time; a TriggInt trap runs there. A Trigg move stops at its ToPoint (the twin does not round its corner zone), so the end point
/// is the ToPoint rather than the middle of the corner path. ContactL moves the same way, without events.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Trigg()
    {
        RapidBuiltinParam[] Outputs() => [Opt("DOp", "signaldo"), Opt("GOp", "signalgo"), Opt("AOp", "signalao"), Opt("ProcID", "num")];
        RapidBuiltinParam[] Move() =>
        [
            Sw("Conc"), P("ToPoint", "robtarget"), Opt("ID", "num"), P("Speed", "speeddata"), Opt("V", "num"), Opt("T", "num"), P("Trigg_1", "triggdata"),
            Opt("T2", "triggdata"), Opt("T3", "triggdata"), Opt("T4", "triggdata"), Opt("T5", "triggdata"), Opt("T6", "triggdata"), Opt("T7", "triggdata"),
            Opt("T8", "triggdata"), P("Zone", "zonedata"), Opt("Inpos", null), P("Tool", "tooldata"), Opt("WObj", "wobjdata"), Sw("Corr"), Opt("TLoad", "loaddata"),
        ];
        return
        [
            Instruction("TriggIO", [P("TriggData", "triggdata", true), P("Distance", "num"), Sw("Start"), Sw("Time"), .. Outputs(), P("SetValue", "num"),
                Opt("DODelay", "num")], call =>
            {
                double delay = call.Has(9) ? call.Num(9) : 0;
                if (delay < 0)
                {
                    throw ArgumentError(call, "TriggIO: \\DODelay must not be negative");
                }
                Define(call, "TriggIO", call.Has(3), delay, OutputOf(call, "TriggIO", 4, 8), call.Num(8), 0, null, ProcIdOf(call, 7));
            }),
            Instruction("TriggEquip", [P("TriggData", "triggdata", true), P("Distance", "num"), Sw("Start"), P("EquipLag", "num"), .. Outputs(), P("SetValue", "num"),
                Opt("Inhib", "bool", true)], call =>
            {
                RapidCall at = call;
                Func<bool>? inhibit = call.Has(9) ? () => (bool)at.Value(9) : null;
                Define(call, "TriggEquip", false, -call.Num(3), OutputOf(call, "TriggEquip", 4, 8), call.Num(8), 0, inhibit, ProcIdOf(call, 7));
            }),
            Instruction("TriggInt", [P("TriggData", "triggdata", true), P("Distance", "num"), Sw("Start"), Sw("Time"), P("Interrupt", "intnum")],
                call => Define(call, "TriggInt", call.Has(3), 0, null, 0, (int)call.Num(4), null)),
            Instruction("TriggL", Move(), call => PieceMove(call, "TriggL", new MoveParams(3, 4, 5, 16, 17), Enumerable.Range(6, 8), linear: true)),
            Instruction("TriggJ", Move(), call => PieceMove(call, "TriggJ", new MoveParams(3, 4, 5, 16, 17), Enumerable.Range(6, 8), linear: false)),
            Instruction("TriggC", [Sw("Conc"), P("CirPoint", "robtarget"), .. Move()[1..]],
                call => PieceMove(call, "TriggC", new MoveParams(4, 5, 6, 17, 18), Enumerable.Range(7, 8), linear: true, toPoint: 2, cirPoint: 1)),
            // ContactL (Collision avoidance, "Contact motion"): the twin has no obstacles to touch, so it moves as a MoveL that stops at its
            // ToPoint (the zone is optional); ERR_CONTACTL (the torque reached \DesiredTorque) never comes.
            Instruction("ContactL", [Opt("DesiredTorque", "num"), P("ToPoint", "robtarget"), Opt("ID", "num"), P("Speed", "speeddata"), Opt("V", "num"), Opt("T", "num"),
                Opt("Zone", "zonedata"), Opt("Z", "num"), Opt("Inpos", null), P("Tool", "tooldata"), Opt("WObj", "wobjdata"), Opt("TLoad", "loaddata")],
                call => PieceMove(call, "ContactL", new MoveParams(3, 4, 5, 9, 10), [], linear: true)),
        ];
    }

    /// <summary>
    /// Stores the event a TriggIO, TriggEquip, TriggInt, TriggCheckIO or TriggSpeed defines in its triggdata (parameter 0; Distance 1,
    /// \Start 2) and returns it.
    /// </summary>
    private static RapidTriggEvent Define(RapidCall call, string name, bool time, double shift, (string, string, int)? signal, double value, int interrupt,
        Func<bool>? inhibit, int? procId = null)
    {
        double distance = call.Num(1);
        if (distance < 0)
        {
            throw ArgumentError(call, $"{name}: the distance {RapidValues.FormatNumber(distance)} must not be negative");
        }
        if (time && call.Has(2))
        {
            throw ArgumentError(call, $"{name}: \\Start and \\Time exclude each other");
        }
        var e = new RapidTriggEvent(distance, call.Has(2), time, shift, signal, value, interrupt, inhibit) { ProcId = procId };
        ((RapidTriggData)call.Value(0)).Event = e;
        return e;
    }

    /// <summary>The \ProcID of parameter <paramref name="p"/> (an IPM process's number), or null without it.</summary>
    private static int? ProcIdOf(RapidCall call, int p) => call.Has(p) ? (int)call.Num(p) : null;

    /// <summary>
    /// The output an event sets (\DOp, \GOp or \AOp from parameter <paramref name="first"/>), with its value checked; null for \ProcID
    /// (parameter first + 3), whose event goes to that process with SetValue as its selector.
    /// </summary>
    private static (string, string, int)? OutputOf(RapidCall call, string name, int first, int value)
    {
        string[] banks = ["do", "go", "ao"];
        int[] given = [.. Enumerable.Range(first, 4).Where(call.Has)];
        if (given.Length != 1)
        {
            throw ArgumentError(call, $"{name}: give exactly one of \\DOp, \\GOp, \\AOp, \\ProcID");
        }
        if (given[0] == first + 3)
        {
            return null;
        }
        string bank = banks[given[0] - first];
        double v = call.Num(value);
        if (bank == "do" && v is not (0 or 1))
        {
            throw ArgumentError(call, $"{name}: the value {RapidValues.FormatNumber(v)} of a digital output is not 0 or 1");
        }
        (string signal, int index) = Signal(call, given[0], bank);
        return (signal, bank, index);
    }

    /// <summary>
    /// A straight (<paramref name="linear"/>), circular (through the <paramref name="cirPoint"/> parameter) or joint move to ToPoint
    /// (parameter <paramref name="toPoint"/>) that stops there, in pieces that end where the events of its <paramref name="triggers"/>
    /// (triggdata parameters) fire, each piece timed as that part of the whole move's speed profile.
    /// </summary>
    private static void PieceMove(RapidCall call, string name, MoveParams p, IEnumerable<int> triggers, bool linear, int toPoint = 1, int? cirPoint = null)
    {
        RapidTask task = call.Machine.Task;
        TwinArm arm = task.Controller.Arm;
        Pose tool = ToolFrame(call, call.Record(p.Tool));
        Pose wobj = call.Has(p.WObj) ? WorkObjectFrame(call, call.Record(p.WObj)) : Pose.Identity;
        arm.FinishBlend(task.CancellationToken); // the twin stops a Trigg move at its ToPoint: the arm stops at the last waypoint first
        Joints from = arm.Joints;
        Pose start = arm.Flange * tool;
        Pose goal = wobj * RapidGeometry.ToPose(call.Record(toPoint), call.Line);
        Joints joints;
        TwinArc? arc = null;
        try
        {
            arm.ToolCenter = tool;
            task.WorkObject = wobj;
            task.UsedFrames(call.Record(p.Tool), call.Has(p.WObj) ? call.Record(p.WObj) : null);
            if (cirPoint is int c)
            {
                Pose middle = wobj * RapidGeometry.ToPose(call.Record(c), call.Line);
                arc = TwinArc.Through(start, middle.Position, goal, TwinArcOrientation.PathRelative) ?? throw CircleError(call);
                if (RapidCircle.Uncertain(call, start.Position, middle.Position, goal.Position) is RapidRuntimeException uncertain)
                {
                    throw uncertain;
                }
                joints = arm.Solve(goal, arm.Solve(middle, from));
                RapidCircle.RequireReachable(arm, arc, from);
            }
            else
            {
                joints = arm.Solve(goal, from);
            }
            arm.RequireWithinLimits(joints);
        }
        catch (TwinMotionException ex)
        {
            throw MotionError(call, ex.Message);
        }
        double mm = arc?.LengthMm ?? (goal.Position - start.Position).Length;
        double seconds = Duration(call, p, mm, TwinRotation.AngleDegrees(start.Rotation, goal.Rotation));
        (double v, double acceleration, _) = Speeds(call, p);
        var profile = new RapidTriggProfile(mm / 1000, v, acceleration, seconds);
        var events = new List<(double At, RapidTriggEvent Event)>();
        foreach (int t in triggers.Where(call.Has))
        {
            if (((RapidTriggData)call.Value(t)).Event is { } e)
            {
                events.Add((When(e, profile), e));
            }
        }
        AddSpeedSamples(events, profile);
        RequireOutsideLimitZones(call, new RapidMovePath(arm, tool, arc, linear, start, goal), from, joints);
        arm.Serve = task.ServeTraps;
        double done = 0, doneFraction = 0;
        Joints near = from;
        var speedOutputs = new Dictionary<RapidTriggEvent, double>(ReferenceEqualityComparer.Instance);
        foreach ((double at, RapidTriggEvent e) in events.OrderBy(x => x.At))
        {
            if (at > done)
            {
                double f = profile.FractionAt(at);
                Joints piece;
                try
                {
                    piece = arc is not null ? arm.Solve(arc.At(f), near)
                        : linear ? arm.Solve(new Pose(start.Position + (goal.Position - start.Position) * f, KinematicChecks.Slerp(start.Rotation, goal.Rotation, f)), from)
                        : Between(from, joints, f);
                }
                catch (TwinMotionException ex)
                {
                    throw MotionError(call, ex.Message);
                }
                arm.MoveTo(piece, at - done, call.Line, name, task.CancellationToken, trace: false, linear: linear, arc: Part(arc, doneFraction, f));
                (done, doneFraction, near) = (at, f, piece);
            }
            double speed = profile.SpeedAt(at - e.ShiftSeconds); // a TriggSpeed output anticipates the speed by its ScaleLag
            if (e.FollowsSpeed && speedOutputs.TryGetValue(e, out double set) && Math.Abs(set - speed) < 1e-9)
            {
                continue; // the speed is the same: the output stays as it is
            }
            Fire(call, e, speed);
            if (e.FollowsSpeed)
            {
                speedOutputs[e] = speed;
            }
        }
        arm.MoveTo(joints, seconds - done, call.Line, name, task.CancellationToken, linear: linear, arc: Part(arc, doneFraction, 1));
        ZoneOutputsAfterMotion(call);
    }

    /// <summary>The times along each ramp of a move at which a TriggSpeed output is set again (an eighth of the ramp apart).</summary>
    private const int SpeedSamplesPerRamp = 8;

    /// <summary>
    /// TriggSpeed: after its event, the output follows the TCP speed; it is set again at <see cref="SpeedSamplesPerRamp"/> points along
    /// each ramp of the move (and at the start of the last one), each ScaleLag earlier, down to 0 where the TCP stops.
    /// </summary>
    private static void AddSpeedSamples(List<(double At, RapidTriggEvent Event)> events, RapidTriggProfile profile)
    {
        foreach ((double at, RapidTriggEvent e) in events.Where(x => x.Event.FollowsSpeed).ToList())
        {
            foreach (double t in profile.RampTimes(SpeedSamplesPerRamp))
            {
                double when = t + e.ShiftSeconds;
                if (when > at && when <= profile.Seconds)
                {
                    events.Add((when, e));
                }
            }
        }
    }

    /// <summary>The part of <paramref name="arc"/> between two fractions of it (null when there is no arc, or the part is too short to be one).</summary>
    private static TwinArc? Part(TwinArc? arc, double from, double to) =>
        arc is null || to <= from ? null : TwinArc.Through(arc.At(from), arc.At((from + to) / 2).Position, arc.At(to), TwinArcOrientation.PathRelative);

    /// <summary>The seconds after a move's start at which an event fires (within the move).</summary>
    private static double When(RapidTriggEvent e, RapidTriggProfile profile)
    {
        double at = e.IsTime ? profile.Seconds - e.Distance
            : profile.Metres <= 0 ? (e.FromStart ? 0 : profile.Seconds) // the tool only turns: at its start or its end
            : profile.TimeAt(e.FromStart ? e.Distance / 1000 : profile.Metres - e.Distance / 1000);
        return Math.Clamp(at + e.ShiftSeconds, 0, profile.Seconds);
    }

    private static Joints Between(Joints a, Joints b, double f) => new(a.J1 + (b.J1 - a.J1) * f, a.J2 + (b.J2 - a.J2) * f, a.J3 + (b.J3 - a.J3) * f,
        a.J4 + (b.J4 - a.J4) * f, a.J5 + (b.J5 - a.J5) * f, a.J6 + (b.J6 - a.J6) * f);

    /// <summary>
    /// Fires an event where the arm is now, the TCP moving at <paramref name="speed"/> m/s: sets its output (traced there), hands it to
    /// its \ProcID process (traced), checks its TriggCheckIO condition, or orders its interrupt and runs the trap there.
    /// </summary>
    private static void Fire(RapidCall call, RapidTriggEvent e, double speed)
    {
        RapidTask task = call.Machine.Task;
        RapidTwinController c = task.Controller;
        if (e.ProcId is int process)
        {
            c.Arm.Record(call.Line, TwinTraceKind.Message, $"ProcID {process}: selector {RapidValues.FormatNumber(e.Value)}");
            return;
        }
        if (e.Check is { } check)
        {
            if (!Holds(c, check))
            {
                if (check.StopMove)
                {
                    c.Arm.Hold(); // the robot stops on its path before the trap runs; the trap's StartMove lets it go on
                }
                task.PostInterrupt(e.Interrupt);
                task.RunPendingTraps();
            }
            return;
        }
        if (e.Signal is not (string name, string bank, int index))
        {
            task.PostInterrupt(e.Interrupt);
            task.RunPendingTraps();
            return;
        }
        double value = e.Inhibit?.Invoke() == true ? 0 : e.FollowsSpeed ? e.Value * speed * 1000 : e.Value;
        if (bank == "do")
        {
            c.SetBit(bank, index, value == 1);
        }
        else
        {
            c.SetNumber(bank, index, value);
        }
        c.Arm.Record(call.Line, TwinTraceKind.Output, $"{name} = {RapidValues.FormatNumber(value)}");
    }
}
