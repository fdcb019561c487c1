namespace Machina.Simulation.Rapid;

/// <summary>
/// Frame arithmetic of the RAPID reference: RelTool, OrientZYX, EulerZYX, PoseMult, PoseInv, PoseVect, NOrient, Distance, DotProd,
/// CrossProd. Angles in degrees, positions in mm.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Frames() =>
    [
        Function("RelTool", "robtarget", [P("Point", "robtarget"), P("Dx", "num"), P("Dy", "num"), P("Dz", "num"), Opt("Rx", "num"), Opt("Ry", "num"), Opt("Rz", "num")], call =>
        {
            // The displacement is in the tool's frame; rotations turn about x, then the new y, then the new z.
            var target = (RapidRecord)RapidValues.Copy(call.Value(0));
            Pose point = RapidGeometry.ToPose(target, call.Line);
            Rotation turn = Rotation.FromAxisAngle(1, 0, 0, call.Has(4) ? call.Num(4) : 0)
                * Rotation.FromAxisAngle(0, 1, 0, call.Has(5) ? call.Num(5) : 0) * Rotation.FromAxisAngle(0, 0, 1, call.Has(6) ? call.Num(6) : 0);
            Pose moved = point * new Pose(new Vector(call.Num(1), call.Num(2), call.Num(3)), turn);
            target.Fields[0] = RapidGeometry.ToPosRecord(moved.Position);
            target.Fields[1] = RapidGeometry.ToOrientRecord(moved.Rotation);
            return target;
        }),
        Function("OrientZYX", "orient", [P("ZAngle", "num"), P("YAngle", "num"), P("XAngle", "num")], call =>
            RapidGeometry.ToOrientRecord(Rotation.FromAxisAngle(0, 0, 1, call.Num(0)) * Rotation.FromAxisAngle(0, 1, 0, call.Num(1))
                * Rotation.FromAxisAngle(1, 0, 0, call.Num(2)))),
        Function("EulerZYX", "num", [Sw("X"), Sw("Y"), Sw("Z"), P("Rotation", "orient")], call =>
        {
            Rotation r = RapidGeometry.ToRotation(call.Record(3), call.Line);
            Vector x = r.XAxis, y = r.YAxis, z = r.ZAxis;
            double degrees = call.Has(0) ? Math.Atan2(y.Z, z.Z) : call.Has(1) ? Math.Asin(Math.Clamp(-x.Z, -1, 1)) : call.Has(2) ? Math.Atan2(x.Y, x.X)
                : throw ArgumentError(call, "EulerZYX: give one of \\X, \\Y or \\Z");
            return degrees * 180 / Math.PI;
        }),
        Function("PoseMult", "pose", [P("Pose1", "pose"), P("Pose2", "pose")], call =>
            RapidGeometry.ToPoseRecord(RapidGeometry.ToPose(call.Record(0), call.Line) * RapidGeometry.ToPose(call.Record(1), call.Line))),
        Function("PoseInv", "pose", [P("Pose", "pose")], call => RapidGeometry.ToPoseRecord(RapidGeometry.ToPose(call.Record(0), call.Line).Inverse())),
        Function("PoseVect", "pos", [P("Pose", "pose"), P("Pos", "pos")], call =>
            RapidGeometry.ToPosRecord(RapidGeometry.ToPose(call.Record(0), call.Line).Transform(RapidGeometry.ToVector(call.Record(1))))),
        Function("NOrient", "orient", [P("Rotation", "orient")], call =>
        {
            RapidRecord q = call.Record(0);
            double w = (double)q.Fields[0], x = (double)q.Fields[1], y = (double)q.Fields[2], z = (double)q.Fields[3];
            double norm = Math.Sqrt(w * w + x * x + y * y + z * z);
            return norm > 0 ? new RapidRecord(RapidTypes.Orient, [w / norm, x / norm, y / norm, z / norm])
                : throw ArgumentError(call, "NOrient: the quaternion is zero");
        }),
        Function("Distance", "num", [P("Point1", "pos"), P("Point2", "pos")], call =>
            (RapidGeometry.ToVector(call.Record(0)) - RapidGeometry.ToVector(call.Record(1))).Length),
        Function("DotProd", "num", [P("Vector1", "pos"), P("Vector2", "pos")], call =>
        {
            Vector a = RapidGeometry.ToVector(call.Record(0)), b = RapidGeometry.ToVector(call.Record(1));
            return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        }),
        Function("CrossProd", "pos", [P("Vector1", "pos"), P("Vector2", "pos")], call =>
        {
            Vector a = RapidGeometry.ToVector(call.Record(0)), b = RapidGeometry.ToVector(call.Record(1));
            return RapidGeometry.ToPosRecord(new Vector(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X));
        }),
    ];
}
