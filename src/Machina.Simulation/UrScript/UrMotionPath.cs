using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>A motion's way: the joints at a fraction of it, and the part of it done some seconds after the start.</summary>
internal interface IUrMotionPath
{
    /// <summary>The joints at <paramref name="fraction"/> (0 to 1) of the way.</summary>
    Joints JointsAt(double fraction);

    /// <summary>The part of the way (0 to 1) done <paramref name="seconds"/> after the start, on the motion's own speed profile.</summary>
    double DoneAt(double seconds);
}

/// <summary>A tool path: the pose at a fraction (0 to 1) of it.</summary>
internal interface IUrWay
{
    /// <summary>The pose at <paramref name="t"/> (0 to 1) of the way.</summary>
    Pose PoseAt(double t);
}

/// <summary>The joints and profile of a motion given as delegates (a blend finishing, an arc, a turn on the spot).</summary>
internal sealed class UrDelegatePath(Func<double, Joints> path, Func<double, double>? profile) : IUrMotionPath
{
    /// <inheritdoc/>
    public Joints JointsAt(double fraction) => path(fraction);

    /// <inheritdoc/>
    public double DoneAt(double seconds) => profile!(seconds);
}

/// <summary>An arc as a tool path (<see cref="UrBuiltins"/>' <c>movec</c>).</summary>
internal readonly struct UrArcWay(TwinArc arc) : IUrWay
{
    /// <inheritdoc/>
    public Pose PoseAt(double t) => arc.At(t);
}

/// <summary>A <c>movel</c> that only turns the tool (shorter than a blend's least length): the joints along its line, each near the straight way in joint space.</summary>
internal sealed class UrTurnPath(TwinArm arm, UrLinearPath way, Joints first, Joints last)
{
    /// <summary>The joints at <paramref name="fraction"/> (0 to 1) of the turn.</summary>
    public Joints JointsAt(double fraction) => fraction >= 1 ? last : UrBuiltins.Near(arm, way.PoseAt(fraction), UrMotion.Lerp(first, last, fraction));
}

/// <summary>A speed motion's way over a fixed time: the fraction of the way is the fraction of the time.</summary>
internal sealed class UrTimedSpeedPath(IUrSpeedWay way, double duration) : IUrMotionPath
{
    /// <inheritdoc/>
    public Joints JointsAt(double fraction) => way.At(fraction * duration);

    /// <inheritdoc/>
    public double DoneAt(double seconds) => seconds / duration;
}
