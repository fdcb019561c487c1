namespace Machina.Simulation;

/// <summary>A motion in progress: the state it started from, the state it ends in, and when.</summary>
internal sealed record VirtualMotion(VirtualAbbState From, VirtualAbbState To, long StartTimestamp, TimeSpan Duration)
{
    /// <summary>The state part-way through the motion at <paramref name="now"/> (a timestamp of the same clock).</summary>
    public VirtualAbbState At(TimeProvider time, long now)
    {
        double t = Duration <= TimeSpan.Zero ? 1 : time.GetElapsedTime(StartTimestamp, now) / Duration;
        if (t >= 1)
        {
            return To;
        }
        t = Math.Max(0, t);
        return To with
        {
            Position = From.Position + (To.Position - From.Position) * t,
            Rotation = Interpolate(From.Rotation, To.Rotation, t),
            Joints = Lerp(From.Joints, To.Joints, t),
        };
    }

    private static Joints Lerp(Joints a, Joints b, double t) => new(
        a.J1 + (b.J1 - a.J1) * t, a.J2 + (b.J2 - a.J2) * t, a.J3 + (b.J3 - a.J3) * t,
        a.J4 + (b.J4 - a.J4) * t, a.J5 + (b.J5 - a.J5) * t, a.J6 + (b.J6 - a.J6) * t);

    /// <summary>Normalised linear interpolation of quaternions along the shorter arc (close enough for a monitor).</summary>
    private static Rotation Interpolate(Rotation a, Rotation b, double t)
    {
        double sign = a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z < 0 ? -1 : 1;
        double w = a.W + (sign * b.W - a.W) * t, x = a.X + (sign * b.X - a.X) * t;
        double y = a.Y + (sign * b.Y - a.Y) * t, z = a.Z + (sign * b.Z - a.Z) * t;
        return w * w + x * x + y * y + z * z < 1e-12 ? b : Rotation.FromQuaternion(w, x, y, z);
    }
}
