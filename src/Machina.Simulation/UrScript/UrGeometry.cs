namespace Machina.Simulation.UrScript;

/// <summary>Conversions between URScript units (metres, radians, rotation vectors) and the library's (mm, degrees, rotations).</summary>
internal static class UrGeometry
{
    private const double Degrees = 180.0 / Math.PI;

    /// <summary>
    /// The largest joint change (degrees, its size) from <paramref name="from"/> to <paramref name="to"/>, without an array: as
    /// <c>(to - from).ToArray().Max(Math.Abs)</c> gives it (a NaN counts only when every change is one).
    /// </summary>
    public static double LargestChange(Joints from, Joints to)
    {
        Joints d = to - from;
        double most = Math.Abs(d.J1);
        foreach (double change in (ReadOnlySpan<double>)[Math.Abs(d.J2), Math.Abs(d.J3), Math.Abs(d.J4), Math.Abs(d.J5), Math.Abs(d.J6)])
        {
            if (change > most || double.IsNaN(most))
            {
                most = change;
            }
        }
        return most;
    }

    /// <summary>A URScript pose <c>p[x, y, z, rx, ry, rz]</c> (m, rad) as a library pose (mm).</summary>
    public static Pose ToPose(double[] six, int line)
    {
        foreach (double v in six)
        {
            if (!double.IsFinite(v))
            {
                throw new UrRuntimeException(line, "a pose element is not a finite number");
            }
        }
        // A finite number of metres or radians can still be past the largest double in millimetres or degrees.
        var position = new Vector(six[0] * 1000, six[1] * 1000, six[2] * 1000);
        var rotation = new Vector(six[3] * Degrees, six[4] * Degrees, six[5] * Degrees);
        if (!position.IsFinite || !rotation.IsFinite)
        {
            throw new UrRuntimeException(line, "a pose element is too large");
        }
        return new Pose(position, Rotation.FromRotationVector(rotation));
    }

    /// <summary>A library pose (mm) as a URScript pose (m, rad).</summary>
    public static UrPose FromPose(Pose pose)
    {
        RotationVector r = pose.Rotation.ToRotationVector();
        return new UrPose([pose.Position.X / 1000, pose.Position.Y / 1000, pose.Position.Z / 1000, r.X / Degrees, r.Y / Degrees, r.Z / Degrees]);
    }

    /// <summary>URScript joint positions (rad) as library joints (degrees).</summary>
    public static Joints ToJoints(double[] six, int line)
    {
        foreach (double v in six)
        {
            if (!double.IsFinite(v))
            {
                throw new UrRuntimeException(line, "a joint position is not a finite number");
            }
        }
        return new Joints(six[0] * Degrees, six[1] * Degrees, six[2] * Degrees, six[3] * Degrees, six[4] * Degrees, six[5] * Degrees);
    }

    /// <summary>Library joints (degrees) as a URScript list of joint positions (rad).</summary>
    public static UrList FromJoints(Joints joints) => new([.. joints.ToArray().Select(d => (object)(d / Degrees))]);

    /// <summary>The rotation part of <paramref name="a"/> to <paramref name="b"/> at fraction <paramref name="t"/> (spherical interpolation).</summary>
    public static Rotation Slerp(Rotation a, Rotation b, double t)
    {
        double dot = a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        double sign = dot < 0 ? -1 : 1;
        dot = Math.Abs(dot);
        double wa, wb;
        if (dot > 0.9995)
        {
            wa = 1 - t;
            wb = t;
        }
        else
        {
            double theta = Math.Acos(dot);
            wa = Math.Sin((1 - t) * theta) / Math.Sin(theta);
            wb = Math.Sin(t * theta) / Math.Sin(theta);
        }
        return Rotation.FromQuaternion(wa * a.W + sign * wb * b.W, wa * a.X + sign * wb * b.X, wa * a.Y + sign * wb * b.Y, wa * a.Z + sign * wb * b.Z);
    }
}
