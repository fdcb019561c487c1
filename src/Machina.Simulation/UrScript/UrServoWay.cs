namespace Machina.Simulation.UrScript;

/// <summary>
/// The way of the arm under <c>servoj(q, t, lookahead_time, gain)</c>. The Script Manual: "The gain parameter works the same way
/// as the P-term of a PID controller, where it adjusts the current position towards the desired (q) ... The parameter
/// lookahead_time is used to project the current position forward in time with the current velocity. A low value gives fast
/// reaction, a high value prevents overshoot." Read so, each joint accelerates at gain times the distance from the position it
/// is projected to (its position plus lookahead_time times its speed) to the target: q'' = gain (q* - q - lookahead q'). From
/// where the arm is at the speeds it has, the way tracks the target (a damped second-order system: critically damped near the
/// defaults 0.1 s and 300) and trails a target that moves at constant speed by lookahead_time times that speed. Joints in
/// degrees, speeds in degrees per second; the gain in 1/s².
/// </summary>
internal sealed class UrServoWay : IUrSpeedWay
{
    /// <summary>How close to the target (degrees) the arm counts as standing on it: from then on the way is the target itself.</summary>
    private const double Settled = 1e-6;

    /// <summary>The longest a way is followed before it counts as settled, seconds (a day).</summary>
    private const double LongestSettle = 86_400;

    private readonly double[] _target, _error, _speed;
    private readonly double _omega, _zeta;

    /// <summary>
    /// The way from <paramref name="from"/> at <paramref name="speeds"/> (degrees per second) towards <paramref name="target"/>
    /// with the servo's <paramref name="lookahead"/> (seconds) and <paramref name="gain"/> (1/s²), both positive.
    /// </summary>
    public UrServoWay(Joints from, double[] speeds, Joints target, double lookahead, double gain)
    {
        _target = target.ToArray();
        double[] q = from.ToArray();
        _error = new double[6];
        _speed = (double[])speeds.Clone();
        for (int i = 0; i < 6; i++)
        {
            _error[i] = q[i] - _target[i];
        }
        // x'' + gain lookahead x' + gain x = 0 for the error x = q - q*: natural frequency sqrt(gain), damping lookahead sqrt(gain) / 2.
        _omega = Math.Sqrt(gain);
        _zeta = lookahead * _omega / 2;
        double settle = 0;
        for (int i = 0; i < 6; i++)
        {
            settle = Math.Max(settle, SettleSeconds(_error[i], _speed[i]));
        }
        Settles = Math.Min(settle, LongestSettle);
    }

    /// <summary>Seconds after the start when every joint is within a millionth of a degree of the target (0: it is there, at rest).</summary>
    public double Settles { get; }

    /// <inheritdoc/>
    public double LimitSeconds => double.PositiveInfinity;

    /// <inheritdoc/>
    public string LimitReason => "";

    /// <inheritdoc/>
    public double KnownUntil => double.PositiveInfinity;

    /// <inheritdoc/>
    public void Extend(double seconds)
    {
    }

    /// <inheritdoc/>
    public Joints At(double seconds)
    {
        if (seconds >= Settles)
        {
            return Joints.FromArray(_target);
        }
        double[] q = new double[6];
        for (int i = 0; i < 6; i++)
        {
            q[i] = _target[i] + Free(_error[i], _speed[i], Math.Max(seconds, 0)).X;
        }
        return Joints.FromArray(q);
    }

    /// <summary>
    /// The fastest each joint moves on this way (degrees per second): at the start, or where its acceleration first changes
    /// sign (on a damped system every later extreme is smaller).
    /// </summary>
    public double[] PeakSpeeds()
    {
        double[] peak = new double[6];
        for (int i = 0; i < 6; i++)
        {
            peak[i] = Math.Abs(_speed[i]);
            if (FirstTurn(_error[i], _speed[i]) is double t)
            {
                peak[i] = Math.Max(peak[i], Math.Abs(Free(_error[i], _speed[i], t).V));
            }
        }
        return peak;
    }

    /// <inheritdoc/>
    public IUrMotionPath Over(double duration) => new UrTimedSpeedPath(this, duration);

    /// <summary>The error and its speed <paramref name="t"/> seconds on, from error <paramref name="e0"/> moving at <paramref name="v0"/>.</summary>
    private (double X, double V) Free(double e0, double v0, double t)
    {
        double w = _omega, z = _zeta;
        if (z < 1 - 1e-9)
        {
            double a = z * w, wd = w * Math.Sqrt(1 - z * z);
            double c1 = e0, c2 = (v0 + a * e0) / wd, decay = Math.Exp(-a * t), cos = Math.Cos(wd * t), sin = Math.Sin(wd * t);
            return (decay * (c1 * cos + c2 * sin), decay * (v0 * cos - (wd * c1 + a * c2) * sin));
        }
        if (z <= 1 + 1e-9)
        {
            double c = v0 + w * e0, decay = Math.Exp(-w * t);
            return (decay * (e0 + c * t), decay * (v0 - w * c * t));
        }
        (double r1, double r2, double p, double q) = Overdamped(e0, v0);
        double e1 = Math.Exp(r1 * t), e2 = Math.Exp(r2 * t);
        return (p * e1 + q * e2, p * r1 * e1 + q * r2 * e2);
    }

    /// <summary>An overdamped servo's two rates (r1 the slower) and the parts of the error on each.</summary>
    private (double R1, double R2, double P, double Q) Overdamped(double e0, double v0)
    {
        double s = _omega * Math.Sqrt(_zeta * _zeta - 1), r1 = -_zeta * _omega + s, r2 = -_zeta * _omega - s;
        double p = (v0 - r2 * e0) / (r1 - r2);
        return (r1, r2, p, e0 - p);
    }

    /// <summary>When the joint's acceleration first passes zero after the start (its speed's first extreme), or null.</summary>
    private double? FirstTurn(double e0, double v0)
    {
        double w = _omega, z = _zeta;
        if (z < 1 - 1e-9)
        {
            double a = z * w, wd = w * Math.Sqrt(1 - z * z);
            double d1 = v0, d2 = -(wd * e0 + a * (v0 + a * e0) / wd);
            double p = -a * d1 + wd * d2, q = wd * d1 + a * d2; // acceleration ~ p cos - q sin
            double angle = q == 0 ? Math.PI / 2 : Math.Atan(p / q);
            if (angle <= 0)
            {
                angle += Math.PI;
            }
            return angle / wd;
        }
        if (z <= 1 + 1e-9)
        {
            double c = v0 + w * e0;
            return c == 0 ? null : (c + v0) / (w * c) is double t && t > 0 ? t : null;
        }
        (double r1, double r2, double pp, double qq) = Overdamped(e0, v0);
        if (pp == 0)
        {
            return null;
        }
        double ratio = -qq * r2 * r2 / (pp * r1 * r1);
        return ratio > 1 ? Math.Log(ratio) / (r1 - r2) : null;
    }

    /// <summary>How long until an error <paramref name="e0"/> moving at <paramref name="v0"/> stays within <see cref="Settled"/> (a bound of its decay).</summary>
    private double SettleSeconds(double e0, double v0)
    {
        double w = _omega, z = _zeta, size, rate;
        if (z < 1 - 1e-9)
        {
            double a = z * w, wd = w * Math.Sqrt(1 - z * z), c2 = (v0 + a * e0) / wd;
            (size, rate) = (Math.Sqrt(e0 * e0 + c2 * c2), a);
        }
        else if (z <= 1 + 1e-9)
        {
            // (|e0| + |c| t) e^(-w t) <= (|e0| + 2 |c| / (e w)) e^(-w t / 2), as t e^(-w t / 2) <= 2 / (e w).
            double c = v0 + w * e0;
            (size, rate) = (Math.Abs(e0) + 2 * Math.Abs(c) / (Math.E * w), w / 2);
        }
        else
        {
            (double r1, _, double p, double q) = Overdamped(e0, v0);
            (size, rate) = (Math.Abs(p) + Math.Abs(q), -r1);
        }
        return size <= Settled ? 0 : Math.Log(size / Settled) / rate;
    }
}
