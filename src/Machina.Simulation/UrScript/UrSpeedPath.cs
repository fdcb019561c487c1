namespace Machina.Simulation.UrScript;

/// <summary>
/// The way of a speed motion in joint space (degrees): from where the arm is at the speeds it has, each joint's speed changing
/// evenly to the asked one over the ramp (all together: the leading joint at the acceleration asked), then constant. Each joint
/// stays within its limits: <see cref="LimitSeconds"/> is when the first one reaches its limit.
/// </summary>
internal sealed class UrSpeedPath : IUrSpeedWay
{
    private const int RampSamples = 64;
    private readonly double[] _from, _start, _speeds, _min, _max;
    private readonly double _ramp;

    /// <summary>The way from <paramref name="from"/>; the speeds in degrees per second.</summary>
    public UrSpeedPath(Joints from, double[] start, double[] speeds, double ramp, double[] min, double[] max)
    {
        (_from, _start, _speeds, _ramp, _min, _max) = (from.ToArray(), start, speeds, ramp, min, max);
        LimitSeconds = double.PositiveInfinity;
        for (int i = 0; i < 6; i++)
        {
            double reached = Reaches(i);
            if (reached < LimitSeconds)
            {
                (LimitSeconds, LimitJoint) = (reached, i);
            }
        }
    }

    /// <summary>Seconds after the start when a joint reaches its position limit (infinite: never).</summary>
    public double LimitSeconds { get; }

    /// <summary>The joint (0 to 5) that reaches its limit first.</summary>
    public int LimitJoint { get; }

    /// <inheritdoc/>
    public string LimitReason => $"joint {LimitJoint + 1} position limit violated";

    /// <inheritdoc/>
    public double KnownUntil => double.PositiveInfinity;

    /// <inheritdoc/>
    public void Extend(double seconds)
    {
    }

    /// <inheritdoc/>
    public Joints At(double seconds)
    {
        double[] q = new double[6];
        for (int i = 0; i < 6; i++)
        {
            q[i] = Math.Clamp(Position(i, seconds), _min[i], _max[i]);
        }
        return Joints.FromArray(q);
    }

    /// <inheritdoc/>
    public IUrMotionPath Over(double duration) => new UrTimedSpeedPath(this, duration);

    /// <summary>Joint <paramref name="i"/>'s position <paramref name="t"/> seconds after the start.</summary>
    private double Position(int i, double t)
    {
        double v0 = _start[i], v = _speeds[i];
        if (t <= _ramp && _ramp > 0)
        {
            return _from[i] + v0 * t + 0.5 * (v - v0) / _ramp * t * t;
        }
        return _from[i] + 0.5 * (v0 + v) * _ramp + v * (t - _ramp);
    }

    /// <summary>When joint <paramref name="i"/> first leaves its limits (infinite: never).</summary>
    private double Reaches(int i)
    {
        bool Outside(double t)
        {
            double q = Position(i, t);
            return q < _min[i] || q > _max[i];
        }
        double before = 0;
        for (int k = 1; k <= RampSamples && _ramp > 0; k++)
        {
            double t = _ramp * k / RampSamples;
            if (Outside(t))
            {
                double low = before, high = t;
                for (int n = 0; n < 60; n++)
                {
                    double mid = 0.5 * (low + high);
                    (low, high) = Outside(mid) ? (low, mid) : (mid, high);
                }
                return low;
            }
            before = t;
        }
        double atRampEnd = Position(i, _ramp), v = _speeds[i];
        return v > 0 ? _ramp + (_max[i] - atRampEnd) / v : v < 0 ? _ramp + (_min[i] - atRampEnd) / v : double.PositiveInfinity;
    }
}
