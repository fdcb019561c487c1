using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Motion instructions (MoveL, MoveJ, MoveAbsJ, MoveC: the tool on the circle through its CirPoint, <see cref="TwinArc"/>) and position
/// functions (CRobT, CJointT, CalcRobT) on the twin arm. A MoveL
/// with a zone returns when the arm enters the zone and the next MoveL rounds the corner (<see cref="TwinArm.MoveLinear"/>), in a
/// program without sockets; every other move, and every move of a program with sockets (our driver), ends at its target. A target out of reach or beyond a joint limit raises ERR_ROBLIMIT with
/// event 50050, which an ERROR handler may take.
/// </summary>
internal static partial class RapidBuiltins
{
    private const double Degrees = 180 / Math.PI;

    /// <summary>The parameters of a move, by index: the target(s), speed, optional \V and \T, tool, optional \WObj.</summary>
    private readonly record struct MoveParams(int Speed, int V, int T, int Tool, int WObj);

    private static IEnumerable<RapidBuiltin> Motion()
    {
        RapidBuiltinParam[] Tail() =>
        [
            Opt("ID", "num"), P("Speed", "speeddata"), Opt("V", "num"), Opt("T", "num"), P("Zone", "zonedata"), Opt("Z", "num"), Opt("Inpos", null),
            P("Tool", "tooldata"), Opt("WObj", "wobjdata"), Sw("Corr"), Opt("TLoad", "loaddata"),
        ];
        var cartesian = new MoveParams(3, 4, 5, 9, 10);
        var circular = new MoveParams(4, 5, 6, 10, 11);
        return
        [
            Instruction("MoveL", [Sw("Conc"), P("ToPoint", "robtarget"), .. Tail()], call => MoveTo(call, "MoveL", call.Record(1), null, cartesian)),
            Instruction("MoveJ", [Sw("Conc"), P("ToPoint", "robtarget"), .. Tail()], call => MoveTo(call, "MoveJ", call.Record(1), null, cartesian)),
            Instruction("MoveC", [Sw("Conc"), P("CirPoint", "robtarget"), P("ToPoint", "robtarget"), .. Tail()],
                call => MoveTo(call, "MoveC", call.Record(2), call.Record(1), circular)),
            Instruction("MoveAbsJ", [Sw("Conc"), P("ToJointPos", "jointtarget"), Sw("NoEOffs"), .. Tail()], call => MoveAbsJ(call, circular)),
            Function("CRobT", "robtarget", [Opt("TaskRef", "num"), Opt("TaskName", "string"), Opt("Tool", "tooldata"), Opt("WObj", "wobjdata")],
                call => CurrentTarget(call, 2, 3)),
            Function("CPos", "pos", [Opt("Tool", "tooldata"), Opt("WObj", "wobjdata")], call => CurrentTarget(call, 0, 1).Fields[0]),
            Function("CTool", "tooldata", [Opt("TaskRef", "num"), Opt("TaskName", "string")],
                call => RapidValues.Copy(call.Machine.Task.ToolData ?? call.Machine.Task.Program.Globals["tool0"].Value)),
            Function("CWObj", "wobjdata", [Opt("TaskRef", "num"), Opt("TaskName", "string")],
                call => RapidValues.Copy(call.Machine.Task.WObjData ?? call.Machine.Task.Program.Globals["wobj0"].Value)),
            Function("CJointT", "jointtarget", [Opt("TaskRef", "num"), Opt("TaskName", "string")],
                call => RapidGeometry.ToJointTarget(call.Machine.Task.Controller.Arm.Joints)),
            Function("CalcRobT", "robtarget", [P("Joint_target", "jointtarget"), P("Tool", "tooldata"), Opt("WObj", "wobjdata")], call =>
            {
                Joints joints = RapidGeometry.ToJoints((RapidRecord)call.Record(0).Fields[0]);
                Pose wobj = call.Has(2) ? WorkObjectFrame(call, call.Record(2)) : Pose.Identity;
                Pose flange = call.Machine.Task.Controller.Arm.Model.Kinematics.Forward(joints);
                return RapidGeometry.ToRobTarget(wobj.Inverse() * flange * ToolFrame(call, call.Record(1)), joints);
            }),
        ];
    }

    /// <summary>CRobT, CPos: where the TCP of the arm is now, through the \Tool and \WObj given (parameters), else the last motion's.</summary>
    private static RapidRecord CurrentTarget(RapidCall call, int toolParam, int wobjParam)
    {
        RapidTwinController c = call.Machine.Task.Controller;
        Joints joints = c.Arm.Joints;
        Pose tool = call.Has(toolParam) ? ToolFrame(call, call.Record(toolParam)) : c.Arm.ToolCenter;
        Pose wobj = call.Has(wobjParam) ? WorkObjectFrame(call, call.Record(wobjParam)) : call.Machine.Task.WorkObject;
        return RapidGeometry.ToRobTarget(wobj.Inverse() * c.Arm.Model.Kinematics.Forward(joints) * tool, joints);
    }

    private static void MoveTo(RapidCall call, string name, RapidRecord target, RapidRecord? via, MoveParams p)
    {
        RapidTask task = call.Machine.Task;
        TwinArm arm = task.Controller.Arm;
        RapidRecord toolData = call.Record(p.Tool, out RapidCellMark toolRead);
        RapidCellMark wobjRead = default;
        RapidRecord? wobjData = call.Has(p.WObj) ? call.Record(p.WObj, out wobjRead) : null;
        bool kept = task.KeepsFrames(toolData, toolRead, wobjData, wobjRead); // the frames of the last move's data, which passed the checks below
        Pose tool = kept ? task.ToolPose : ToolFrame(call, toolData);
        Pose wobj = wobjData is null ? Pose.Identity : kept ? task.WObjPose : WorkObjectFrame(call, wobjData);
        bool linear = name == "MoveL";
        if (!linear || call.Has(p.T) || tool != arm.ToolCenter)
        {
            arm.FinishBlend(task.CancellationToken); // only a MoveL with the same tool rounds the corner: the arm stops first
        }
        TwinBlend? blend = arm.PendingBlend;
        Joints stands = arm.Joints; // read once: each read takes the arm's gate
        Pose start = blend?.Corner ?? arm.FlangeAt(stands) * tool;
        Joints near = blend?.CornerJoints ?? stands;
        Pose goal = wobj * RapidGeometry.ToPose(target, call.Line);
        Joints joints;
        double path;
        TwinArc? arc = null;
        try
        {
            arm.ToolCenter = tool;
            task.WorkObject = wobj;
            if (!kept)
            {
                task.UsedFrames(toolData, toolRead, wobjData, wobjRead, tool, wobj);
            }
            if (via is not null)
            {
                Pose middle = wobj * RapidGeometry.ToPose(via, call.Line);
                arc = TwinArc.Through(start, middle.Position, goal, TwinArcOrientation.PathRelative) ?? throw CircleError(call);
                if (RapidCircle.Uncertain(call, start.Position, middle.Position, goal.Position) is RapidRuntimeException uncertain)
                {
                    throw uncertain;
                }
                Joints viaJoints = arm.Solve(middle, near);
                joints = arm.Solve(goal, viaJoints);
                RapidCircle.RequireReachable(arm, arc, near);
                path = arc.LengthMm;
            }
            else
            {
                joints = arm.Solve(goal, near);
                path = (goal.Position - start.Position).Length;
            }
            arm.RequireWithinLimits(joints);
        }
        catch (TwinMotionException ex)
        {
            throw MotionError(call, ex.Message);
        }
        double seconds = Duration(call, p, path, TwinRotation.AngleDegrees(start.Rotation, goal.Rotation));
        Joints startJoints = near;
        RequireOutsideLimitZones(call, new RapidMovePath(arm, tool, arc, linear, start, goal), startJoints, joints);
        arm.Serve = task.ServeTraps; // interrupts are served while the motion runs (a trap may hold or clear it)
        if (!linear || call.Has(p.T))
        {
            arm.MoveTo(joints, seconds, call.Line, name, task.CancellationToken, linear: linear, arc: arc);
            ZoneOutputsAfterMotion(call);
            return;
        }
        (double v, double acceleration, _) = Speeds(call, p);
        double zone = Zone(call, p);
        arm.MoveLinear(new TwinLinearMove(goal, joints, v, acceleration, seconds, zone, zone > 0 && !task.Controller.HasSockets), call.Line, name, task.CancellationToken);
        ZoneOutputsAfterMotion(call);
    }

    /// <summary>
    /// The zone radius of a move in mm (RAPID reference, zonedata): pzone_tcp, or \Z when given; 0 for a stop point (fine, finep
    /// TRUE, or \Inpos). The twin rounds the TCP path only: pzone_ori and zone_ori do not shorten it.
    /// </summary>
    private static double Zone(RapidCall call, MoveParams p)
    {
        RapidRecord zone = call.Record(p.T + 1);
        if ((bool)zone.Fields[0] || call.Has(p.T + 3))
        {
            return 0;
        }
        double radius = call.Has(p.T + 2) ? call.Num(p.T + 2) : (double)zone.Fields[1];
        return radius > 0 ? radius : 0;
    }

    private static void MoveAbsJ(RapidCall call, MoveParams p)
    {
        RapidTask task = call.Machine.Task;
        TwinArm arm = task.Controller.Arm;
        Pose tool = ToolFrame(call, call.Record(p.Tool));
        Joints joints = RapidGeometry.ToJoints((RapidRecord)call.Record(1).Fields[0]);
        arm.FinishBlend(task.CancellationToken); // a joint move does not round the corner: the arm stops at the last waypoint first
        try
        {
            arm.RequireWithinLimits(joints);
        }
        catch (TwinMotionException ex)
        {
            throw MotionError(call, ex.Message);
        }
        Pose start = arm.Flange * tool;
        arm.ToolCenter = tool;
        task.WorkObject = call.Has(p.WObj) ? WorkObjectFrame(call, call.Record(p.WObj)) : Pose.Identity;
        task.UsedFrames(call.Record(p.Tool), call.Has(p.WObj) ? call.Record(p.WObj) : null);
        Pose goal = arm.Model.Kinematics.Forward(joints) * tool;
        double seconds = Duration(call, p, (goal.Position - start.Position).Length, TwinRotation.AngleDegrees(start.Rotation, goal.Rotation));
        Joints from = arm.Joints;
        RequireOutsideLimitZones(call, new RapidMovePath(arm, tool, null, false, start, goal), from, joints);
        arm.Serve = task.ServeTraps;
        arm.MoveTo(joints, seconds, call.Line, "MoveAbsJ", task.CancellationToken);
        ZoneOutputsAfterMotion(call);
    }

    /// <summary>Seconds a move takes: \T when given, else the TCP path at the programmed speed (VelSet applied) with the acceleration ramps, or the reorientation at v_ori when it is longer.</summary>
    private static double Duration(RapidCall call, MoveParams p, double mm, double degrees)
    {
        if (call.Has(p.T))
        {
            double t = call.Num(p.T);
            return t > 0 ? t : throw ArgumentError(call, "the time \\T must be positive");
        }
        (double v, double acceleration, double vOri) = Speeds(call, p);
        return Math.Max(TwinMotion.TrapezoidSeconds(mm / 1000, v, acceleration), degrees / vOri);
    }

    /// <summary>The TCP speed (m/s, VelSet's override and maximum applied), acceleration (m/s², WorldAccLim and AccSet) and v_ori (deg/s) of a move.</summary>
    private static (double Speed, double Acceleration, double Ori) Speeds(RapidCall call, MoveParams p)
    {
        RapidTask task = call.Machine.Task;
        RapidRecord speed = call.Record(p.Speed);
        double vTcp = call.Has(p.V) ? call.Num(p.V) : (double)speed.Fields[0], vOri = (double)speed.Fields[1];
        if (!(vTcp > 0) || !(vOri > 0))
        {
            throw ArgumentError(call, "the speed must be positive (speeddata v_tcp and v_ori)");
        }
        double v = Math.Min(vTcp * task.SpeedOverride / 100, task.MaxSpeed) / 1000;
        double acceleration = (task.AccelerationLimit ?? task.Controller.Options.Acceleration) * task.AccelerationPercent / 100;
        return (v, acceleration, vOri);
    }

    /// <summary>A MoveC whose start, CirPoint and ToPoint do not define a circle (two closer than 0.1 mm, or all on one line).</summary>
    private static RapidRuntimeException CircleError(RapidCall call) => ArgumentError(call, FormattableString.Invariant(
        $"MoveC: the start point, CirPoint and ToPoint do not define a circle {TwinArc.NotACircle}"));

    private static RapidRuntimeException MotionError(RapidCall call, string detail) =>
        new(RapidErrorNumbers.RobLimit, call.Line, $"Position outside reach: {detail}") { Event = 50050 };

    /// <summary>The TCP frame of a tooldata, relative to the flange; a stationary tool (robhold FALSE) is refused.</summary>
    private static Pose ToolFrame(RapidCall call, RapidRecord tool)
    {
        if (!(bool)tool.Fields[0])
        {
            throw ArgumentError(call, "the twin has no stationary tools: tooldata robhold must be TRUE");
        }
        if ((double)((RapidRecord)tool.Fields[2]).Fields[0] <= 0)
        {
            throw ArgumentError(call, "the tool's load has no mass (tooldata tload.mass must be positive)");
        }
        return RapidGeometry.ToPose((RapidRecord)tool.Fields[1], call.Line);
    }

    /// <summary>The frame of a wobjdata (user frame then object frame); a work object moved by the robot is refused.</summary>
    private static Pose WorkObjectFrame(RapidCall call, RapidRecord wobj)
    {
        if ((bool)wobj.Fields[0])
        {
            throw ArgumentError(call, "the twin has no work objects held by the robot: wobjdata robhold must be FALSE");
        }
        return RapidGeometry.ToPose((RapidRecord)wobj.Fields[3], call.Line) * RapidGeometry.ToPose((RapidRecord)wobj.Fields[4], call.Line);
    }
}
