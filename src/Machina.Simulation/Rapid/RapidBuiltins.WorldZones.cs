using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// World Zones (RAPID reference: WZBoxDef, WZCylDef, WZSphDef, WZLimJointDef, WZHomeJointDef, WZLimSup, WZDOSet, WZEnable, WZDisable,
/// WZFree): a shape in world coordinates or a joint space, activated as a limit zone that the TCP may not enter (a motion whose path would take it in is refused before the arm
/// moves, and the task stops: the controller stops the robot at the zone's border) or as an output zone whose digital output tells
/// whether the TCP is in it (set when the zone is activated and after each motion, at the arm's position then).
/// </summary>
internal static partial class RapidBuiltins
{
    /// <summary>Points a motion's path is checked at against the limit zones (besides its end).</summary>
    private const int ZoneSamples = 64;

    private static IEnumerable<RapidBuiltin> WorldZones() =>
    [
        Instruction("WZBoxDef", [Sw("Inside"), Sw("Outside"), P("Shape", "shapedata", true), P("LowPoint", "pos"), P("HighPoint", "pos")], call =>
        {
            Vector low = RapidGeometry.ToVector(call.Record(3)), high = RapidGeometry.ToVector(call.Record(4));
            if (!(low.X < high.X && low.Y < high.Y && low.Z < high.Z))
            {
                throw ArgumentError(call, "WZBoxDef: the LowPoint must be below the HighPoint in x, y and z");
            }
            ((RapidShape)call.Value(2)).Box(Outside(call, "WZBoxDef"), low, high);
        }),
        Instruction("WZCylDef", [Sw("Inside"), Sw("Outside"), P("Shape", "shapedata", true), P("CentrePoint", "pos"), P("Radius", "num"), P("Height", "num")], call =>
        {
            if (!(call.Num(4) > 0) || call.Num(5) == 0)
            {
                throw ArgumentError(call, "WZCylDef: the radius must be positive and the height not 0");
            }
            ((RapidShape)call.Value(2)).Cylinder(Outside(call, "WZCylDef"), RapidGeometry.ToVector(call.Record(3)), call.Num(4), call.Num(5));
        }),
        Instruction("WZSphDef", [Sw("Inside"), Sw("Outside"), P("Shape", "shapedata", true), P("CentrePoint", "pos"), P("Radius", "num")], call =>
        {
            if (!(call.Num(4) > 0))
            {
                throw ArgumentError(call, "WZSphDef: the radius must be positive");
            }
            ((RapidShape)call.Value(2)).Sphere(Outside(call, "WZSphDef"), RapidGeometry.ToVector(call.Record(3)), call.Num(4));
        }),
        Instruction("WZLimJointDef", [Sw("Inside"), Sw("Outside"), P("Shape", "shapedata", true), P("LowJointVal", "jointtarget"), P("HighJointVal", "jointtarget")], call =>
        {
            double[] low = RobotAxes(call.Record(3)), high = RobotAxes(call.Record(4));
            if (Enumerable.Range(0, low.Length).Any(i => Supervised(low[i]) != Supervised(high[i]) || (Supervised(low[i]) && low[i] > high[i])))
            {
                throw ArgumentError(call, "WZLimJointDef: each supervised axis needs a LowJointVal below its HighJointVal (9E9 in both leaves an axis out)");
            }
            ((RapidShape)call.Value(2)).JointSpace(Outside(call, "WZLimJointDef"), low, high);
        }),
        Instruction("WZHomeJointDef", [Sw("Inside"), Sw("Outside"), P("Shape", "shapedata", true), P("MiddleJointVal", "jointtarget"), P("DeltaJointVal", "jointtarget")], call =>
        {
            double[] middle = RobotAxes(call.Record(3)), delta = RobotAxes(call.Record(4));
            if (Enumerable.Range(0, middle.Length).Any(i => Supervised(middle[i]) && !(delta[i] > 0 && Supervised(delta[i]))))
            {
                throw ArgumentError(call, "WZHomeJointDef: each supervised axis needs a positive DeltaJointVal (9E9 in MiddleJointVal leaves an axis out)");
            }
            double[] low = [.. middle.Select((m, i) => Supervised(m) ? m - delta[i] : 9E9)];
            double[] high = [.. middle.Select((m, i) => Supervised(m) ? m + delta[i] : 9E9)];
            ((RapidShape)call.Value(2)).JointSpace(Outside(call, "WZHomeJointDef"), low, high);
        }),
        Instruction("WZLimSup", [Sw("Temp"), Sw("Stat"), P("WorldZone", null, true), P("Shape", "shapedata")], call =>
        {
            RapidWorldZone zone = ActivatedZone(call, "WZLimSup", 2, 3);
            zone.Limits = true;
            zone.Output = null;
            TwinArm arm = call.Machine.Task.Controller.Arm;
            if (zone.Shape!.Contains(arm.Tcp.Position, arm.Joints))
            {
                throw ArgumentError(call, "WZLimSup: the robot is in the zone already");
            }
            call.Machine.Task.Controller.Activate(zone);
        }),
        Instruction("WZDOSet", [Sw("Temp"), Sw("Stat"), P("WorldZone", null, true), Sw("Inside"), Sw("Before"), P("Shape", "shapedata"), P("Signal", "signaldo"),
            P("SetValue", "dionum")], call =>
        {
            if (call.Has(3) == call.Has(4))
            {
                throw ArgumentError(call, "WZDOSet: give one of \\Inside and \\Before");
            }
            double value = call.Num(7);
            if (value is not (0 or 1))
            {
                throw ArgumentError(call, $"WZDOSet: the value {RapidValues.FormatNumber(value)} is not 0 or 1");
            }
            RapidWorldZone zone = ActivatedZone(call, "WZDOSet", 2, 5);
            (string name, int index) = Signal(call, 6, "do");
            zone.Limits = false;
            zone.Output = (name, index, value == 1);
            call.Machine.Task.Controller.Activate(zone);
        }),
        Instruction("WZEnable", [P("WorldZone", "wztemporary", true)], call => Temporary(call, "WZEnable").Enabled = true),
        Instruction("WZDisable", [P("WorldZone", "wztemporary", true)], call => Temporary(call, "WZDisable").Enabled = false),
        Instruction("WZFree", [P("WorldZone", "wztemporary", true)], call => call.Machine.Task.Controller.Free(Temporary(call, "WZFree"))),
    ];

    /// <summary>The six robot axes of a jointtarget (its robax), in degrees.</summary>
    private static double[] RobotAxes(RapidRecord jointtarget) => [.. ((RapidRecord)jointtarget.Fields[0]).Fields.Select(f => (double)f)];

    /// <summary>False for 9E9, the value that leaves an axis out of a joint zone.</summary>
    private static bool Supervised(double value) => Math.Abs(value) < 9E8;

    private static bool Outside(RapidCall call, string name) => call.Has(0) != call.Has(1)
        ? call.Has(1)
        : throw ArgumentError(call, $"{name}: give one of \\Inside and \\Outside");

    /// <summary>The world zone of parameter <paramref name="p"/>, of the kind \Temp or \Stat says, with the shape of parameter <paramref name="shape"/>.</summary>
    private static RapidWorldZone ActivatedZone(RapidCall call, string name, int p, int shape)
    {
        if (call.Value(p) is not RapidWorldZone zone)
        {
            throw ArgumentError(call, $"{name}: the world zone must be a wzstationary or wztemporary");
        }
        bool stationary = call.TypeOf(p)?.Element.Name.Equals("wzstationary", StringComparison.OrdinalIgnoreCase) == true;
        if (call.Has(0) == call.Has(1) || call.Has(1) != stationary)
        {
            throw ArgumentError(call, $"{name}: a wzstationary takes \\Stat, a wztemporary \\Temp");
        }
        var s = (RapidShape)call.Value(shape);
        if (s.Kind is null)
        {
            throw ArgumentError(call, $"{name}: the shape is not defined (WZBoxDef, WZCylDef or WZSphDef first)");
        }
        zone.Shape = s.Copy();
        zone.Stationary = stationary;
        zone.Enabled = true;
        zone.Line = call.Line;
        return zone;
    }

    private static RapidWorldZone Temporary(RapidCall call, string name) => call.Value(0) is RapidWorldZone { Shape: not null, Stationary: false } zone
        ? zone
        : throw ArgumentError(call, $"{name}: the world zone is not an active wztemporary");

    /// <summary>
    /// The limit zones' check of a move from <paramref name="from"/> to <paramref name="to"/> (<see cref="RequireOutsideLimitZones(RapidCall, Func{double, Vector}, Joints, Joints)"/>)
    /// when the task has zones: the TCP's path is made only then (a closure over the move's values, which every move made before).
    /// </summary>
    private static void RequireOutsideLimitZones(RapidCall call, RapidMovePath path, Joints from, Joints to)
    {
        if (call.Machine.Task.Controller.HasZones)
        {
            RequireOutsideLimitZones(call, path.TcpAt(from, to), from, to);
        }
    }

    /// <summary>
    /// Refuses a motion whose path (<paramref name="tcpAt"/> of the fraction of the way, the joints going from <paramref name="from"/> to
    /// <paramref name="to"/>) would enter a limit zone: the task stops (no ERROR handler takes it), the arm where it stands. A joint zone is checked on the
    /// joints interpolated from the start to the target (the joint path of MoveJ and MoveAbsJ; for MoveL and MoveC, their ends exactly).
    /// </summary>
    private static void RequireOutsideLimitZones(RapidCall call, Func<double, Vector> tcpAt, Joints from, Joints to)
    {
        RapidTwinController c = call.Machine.Task.Controller;
        if (c.LimitZoneOn(Enumerable.Range(1, ZoneSamples).Select(i => (double)i / ZoneSamples).Select(f => (tcpAt(f), Between(from, to, f)))) is { } zone)
        {
            throw new RapidRuntimeException(RapidErrorNumbers.ArgValErr, call.Line,
                $"World zone: the motion would take {(zone.Shape!.Kind == "joints" ? "the robot's axes" : "the TCP")} into the limit zone activated at line {zone.Line} (WZLimSup); the robot stops at its border")
            { Fatal = true };
        }
    }

    /// <summary>After a motion: the outputs of WZDOSet zones follow where the TCP is now.</summary>
    private static void ZoneOutputsAfterMotion(RapidCall call)
    {
        RapidTwinController c = call.Machine.Task.Controller;
        if (c.HasZones)
        {
            c.UpdateZoneOutputs(c.Arm.Tcp.Position, c.Arm.Joints);
        }
    }
}
