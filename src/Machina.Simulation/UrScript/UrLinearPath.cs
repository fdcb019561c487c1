using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// The way of one <c>movel</c> or <c>movep</c>, in one object: the straight line from its start to its target (the tool turning
/// evenly), the blend around the last waypoint that it begins with, and its own speed profile. The motion asks it where the arm is
/// part-way and how much of the way is done (<see cref="IUrMotionPath"/>) instead of calling a closure's delegates: one object per
/// motion where a closure of every local and three delegates were allocated.
/// </summary>
internal sealed class UrLinearPath(TwinArm arm, Pose start, Pose target) : IUrMotionPath, IUrWay
{
    /// <summary>The blend the motion begins with (null: none).</summary>
    public UrBlend? Blend { get; set; }

    /// <summary>The length of the straight line, m.</summary>
    public double Metres { get; set; }

    /// <summary>How far along this motion's line the blend's exit is, m.</summary>
    public double ExitLeg { get; set; }

    /// <summary>The length of the blend's arc, m.</summary>
    public double BlendLength { get; set; }

    /// <summary>How long the blend takes, s.</summary>
    public double BlendSeconds { get; set; }

    /// <summary>The speed at the blend, m/s.</summary>
    public double StartSpeed { get; set; }

    /// <summary>The speed profile of the straight part after the blend.</summary>
    public SpeedProfile Profile { get; set; }

    /// <summary>The blend's arc and the straight part, m.</summary>
    public double Total { get; set; }

    /// <summary>Where the arm's joints are when the motion starts.</summary>
    public Joints StartJoints { get; set; }

    /// <summary>The joints at the motion's end (its own blend's entry when it blends).</summary>
    public Joints End { get; set; }

    /// <summary>The pose at <paramref name="t"/> (0 to 1) of the straight line.</summary>
    public Pose PoseAt(double t) => new(start.Position + (target.Position - start.Position) * t, UrGeometry.Slerp(start.Rotation, target.Rotation, t));

    /// <summary>The pose <paramref name="s"/> metres along this motion's way: on the blend's arc first, then on the line.</summary>
    public Pose At(double s)
    {
        if (s < BlendLength && Blend is not null)
        {
            Pose exit = PoseAt(ExitLeg / Metres);
            Vector point = BlendModel.PointAtDistance(Blend.Entry.Position / 1000, start.Position / 1000, exit.Position / 1000, s) * 1000;
            return new Pose(point, UrGeometry.Slerp(Blend.Entry.Rotation, exit.Rotation, s / BlendLength));
        }
        return PoseAt(Math.Min(1, (ExitLeg + s - BlendLength) / Metres));
    }

    /// <inheritdoc/>
    public Joints JointsAt(double fraction) => fraction >= 1 ? End : UrBuiltins.Near(arm, At(fraction * Total), UrMotion.Lerp(StartJoints, End, fraction));

    /// <inheritdoc/>
    public double DoneAt(double seconds) =>
        Total <= 0 ? 1 : (seconds < BlendSeconds ? StartSpeed * seconds : BlendLength + Profile.DistanceAt(seconds - BlendSeconds)) / Total;
}
