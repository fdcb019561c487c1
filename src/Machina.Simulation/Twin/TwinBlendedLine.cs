namespace Machina.Simulation.Twin;

/// <summary>
/// The way of a linear motion that may round the corner before it (<see cref="TwinArm.MoveLinear"/>): from the zone's entry of a
/// pending <paramref name="Blend"/> past its waypoint <paramref name="Start"/> to the exit leg (<paramref name="Exit"/>,
/// <paramref name="ExitLeg"/> m along this motion), then straight on to <paramref name="Target"/>; <paramref name="Metres"/> the
/// straight line's length, <paramref name="BlendLength"/> the blend's (0 without one). A value: planning a motion makes no object.
/// </summary>
internal readonly record struct TwinBlendedLine(Pose Start, Pose Target, Pose Exit, TwinBlend? Blend, double Metres, double ExitLeg, double BlendLength)
{
    /// <summary>The tool on the straight line from <see cref="Start"/> to <see cref="Target"/>, <paramref name="t"/> of the way (0-1).</summary>
    public static Pose Straight(Pose start, Pose target, double t) =>
        new(start.Position + (target.Position - start.Position) * t, KinematicChecks.Slerp(start.Rotation, target.Rotation, t));

    /// <summary>The tool <paramref name="s"/> metres along this motion's way (the blend first, then the straight line).</summary>
    public Pose At(double s)
    {
        if (s < BlendLength && Blend is { } blend)
        {
            Vector point = BlendModel.PointAtDistance(blend.Entry.Position / 1000, Start.Position / 1000, Exit.Position / 1000, s) * 1000;
            return new Pose(point, KinematicChecks.Slerp(blend.Entry.Rotation, Exit.Rotation, s / BlendLength));
        }
        return Straight(Start, Target, Math.Min(1, (ExitLeg + s - BlendLength) / Metres));
    }
}
