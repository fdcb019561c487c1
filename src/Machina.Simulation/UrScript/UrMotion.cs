namespace Machina.Simulation.UrScript;

/// <summary>
/// One motion of the arm in progress: from where it started to its target, the part of the whole way already behind when it
/// started (after a stop), when it started, how long it takes and how long its speed ramps take (or its own speed profile: the
/// part of its own way done after some seconds), and the path it follows.
/// </summary>
/// <remarks>The path (null: straight in joint space) gives the joints at a fraction of the way; its own speed profile is followed
/// when <paramref name="ownProfile"/> (else the trapezoid's).</remarks>
internal sealed class UrMotion(Joints from, Joints target, double doneBefore, long started, double seconds, double rampSeconds, IUrMotionPath? path,
    bool ownProfile = false)
{
    /// <summary>Where the motion goes.</summary>
    public Joints Target => target;

    /// <summary>
    /// A speed motion (<c>speedj</c>, <c>speedl</c>): it goes on after the call that started it returned, until a motion or stop
    /// of its thread replaces it, a hold or the program's end stops it, or a joint reaches its limit.
    /// </summary>
    public bool OpenEnded { get; init; }

    /// <summary>When the motion started, as a timestamp of the controller's time.</summary>
    public long Started { get; } = started;

    /// <summary>How long it takes, in seconds (0: it ends at once).</summary>
    public TimeSpan Duration => TimeSpan.FromSeconds(seconds);

    /// <summary>The fraction of the whole way (0 to 1) reached <paramref name="elapsed"/> after the start, on the trapezoid profile.</summary>
    public double FractionAt(TimeSpan elapsed)
    {
        double t = Math.Clamp(elapsed.TotalSeconds, 0, seconds);
        double own = seconds <= 0 ? 1 : ownProfile && path is not null ? Math.Clamp(path.DoneAt(t), 0, 1) : Profile(t);
        return doneBefore + (1 - doneBefore) * own;
    }

    /// <summary>The joints <paramref name="elapsed"/> after the start.</summary>
    public Joints At(TimeSpan elapsed)
    {
        double f = FractionAt(elapsed);
        if (path is not null)
        {
            return path.JointsAt(f);
        }
        double own = doneBefore >= 1 ? 1 : (f - doneBefore) / (1 - doneBefore);
        return Lerp(from, target, own);
    }

    /// <summary>The joints <paramref name="t"/> of the way from <paramref name="a"/> to <paramref name="b"/>, each joint straight.</summary>
    public static Joints Lerp(Joints a, Joints b, double t) =>
        new(a.J1 + (b.J1 - a.J1) * t, a.J2 + (b.J2 - a.J2) * t, a.J3 + (b.J3 - a.J3) * t, a.J4 + (b.J4 - a.J4) * t, a.J5 + (b.J5 - a.J5) * t, a.J6 + (b.J6 - a.J6) * t);

    /// <summary>The part of this motion's own way done at <paramref name="t"/> seconds: accelerate, cruise, decelerate.</summary>
    private double Profile(double t)
    {
        double ramp = rampSeconds;
        if (ramp <= 0)
        {
            return t / seconds;
        }
        double peak = 1 / (seconds - ramp); // the cruise speed that covers the whole way
        double acceleration = peak / ramp;
        if (t < ramp)
        {
            return 0.5 * acceleration * t * t;
        }
        if (t <= seconds - ramp)
        {
            return 0.5 * acceleration * ramp * ramp + peak * (t - ramp);
        }
        double left = seconds - t;
        return 1 - 0.5 * acceleration * left * left;
    }
}
