namespace Machina.Simulation;

/// <summary>
/// A motion in progress: the state it started from, the state it ends in, and when. A linear move interpolates the pose and,
/// with a model, solves the joints at each point; a joint move interpolates the joints and, with a model, computes the pose.
/// </summary>
internal sealed record VirtualMotion(VirtualRobotState From, VirtualRobotState To, long StartTimestamp, TimeSpan Duration, bool InJointSpace, RobotModel? Model)
{
    /// <summary>The state part-way through the motion at <paramref name="now"/> (a timestamp of the same clock).</summary>
    public VirtualRobotState At(TimeProvider time, long now)
    {
        double t = Duration <= TimeSpan.Zero ? 1 : time.GetElapsedTime(StartTimestamp, now) / Duration;
        if (t >= 1)
        {
            return To;
        }
        t = Math.Max(0, t);
        if (InJointSpace)
        {
            Joints joints = Lerp(From.Joints, To.Joints, t);
            if (Model is not null)
            {
                Pose tcp = Model.Kinematics.Forward(joints) * (To.Tool ?? Pose.Identity);
                return To with { Position = tcp.Position, Rotation = tcp.Rotation, Joints = joints };
            }
            return To with { Position = From.Position + (To.Position - From.Position) * t, Rotation = Interpolate(From.Rotation, To.Rotation, t), Joints = joints };
        }
        var position = From.Position + (To.Position - From.Position) * t;
        var rotation = Interpolate(From.Rotation, To.Rotation, t);
        Joints? solved = Model?.Kinematics.Closest(new Pose(position, rotation) * (To.Tool ?? Pose.Identity).Inverse(), From.Joints);
        return To with { Position = position, Rotation = rotation, Joints = solved ?? Lerp(From.Joints, To.Joints, t) };
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
