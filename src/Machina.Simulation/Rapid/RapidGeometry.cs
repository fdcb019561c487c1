namespace Machina.Simulation.Rapid;

/// <summary>Conversions between RAPID records (pos, orient, pose, robtarget, jointtarget) and the library's geometry.</summary>
internal static class RapidGeometry
{
    /// <summary>The value RAPID uses for an external axis that is not there.</summary>
    public const double NoAxis = 9E9;

    /// <summary>A pos record as a vector (mm).</summary>
    public static Vector ToVector(RapidRecord pos) => new((double)pos.Fields[0], (double)pos.Fields[1], (double)pos.Fields[2]);

    /// <summary>A vector as a pos record.</summary>
    public static RapidRecord ToPosRecord(Vector v) => new(RapidTypes.Pos, [v.X, v.Y, v.Z]);

    /// <summary>An orient record (q1 scalar first) as a rotation; a quaternion that is far from unit length is refused.</summary>
    public static Rotation ToRotation(RapidRecord orient, int line)
    {
        double w = (double)orient.Fields[0], x = (double)orient.Fields[1], y = (double)orient.Fields[2], z = (double)orient.Fields[3];
        double norm = Math.Sqrt(w * w + x * x + y * y + z * z);
        if (Math.Abs(norm - 1) > 0.001)
        {
            throw new RapidRuntimeException(RapidErrorNumbers.ArgValErr, line,
                $"the orientation is not normalized (its quaternion has length {RapidValues.FormatNumber(Math.Round(norm, 4))})") { Event = 40676 };
        }
        return Rotation.FromQuaternion(w, x, y, z);
    }

    /// <summary>A rotation as an orient record.</summary>
    public static RapidRecord ToOrientRecord(Rotation r) => new(RapidTypes.Orient, [r.W, r.X, r.Y, r.Z]);

    /// <summary>A pose-shaped record (pose, or the first two components of a robtarget: trans and rot).</summary>
    public static Pose ToPose(RapidRecord record, int line) =>
        new(ToVector((RapidRecord)record.Fields[0]), ToRotation((RapidRecord)record.Fields[1], line));

    /// <summary>A pose as a pose record.</summary>
    public static RapidRecord ToPoseRecord(Pose pose) => new(RapidTypes.PoseType, [ToPosRecord(pose.Position), ToOrientRecord(pose.Rotation)]);

    /// <summary>A robjoint record (degrees) as joints.</summary>
    public static Joints ToJoints(RapidRecord robjoint) => Joints.FromArray([.. robjoint.Fields.Select(f => (double)f)]);

    /// <summary>No external axes: every component 9E9.</summary>
    public static RapidRecord NoExternalAxes() => new(RapidTypes.Extjoint, [NoAxis, NoAxis, NoAxis, NoAxis, NoAxis, NoAxis]);

    /// <summary>A jointtarget at <paramref name="joints"/> with no external axes.</summary>
    public static RapidRecord ToJointTarget(Joints joints) =>
        new(RapidTypes.Jointtarget, [new RapidRecord(RapidTypes.Robjoint, [.. joints.ToArray().Select(d => (object)d)]), NoExternalAxes()]);

    /// <summary>A robtarget at <paramref name="pose"/>, with the axis quadrants of <paramref name="joints"/> (cf1, cf4, cf6).</summary>
    public static RapidRecord ToRobTarget(Pose pose, Joints joints)
    {
        var conf = new RapidRecord(RapidTypes.Confdata, [Quadrant(joints.J1), Quadrant(joints.J4), Quadrant(joints.J6), 0.0]);
        return new RapidRecord(RapidTypes.Robtarget, [ToPosRecord(pose.Position), ToOrientRecord(pose.Rotation), conf, NoExternalAxes()]);
    }

    private static object Quadrant(double degrees) => Math.Floor(degrees / 90);
}
