using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Where the TCP is along a straight move at a time, and when it passes a point of it: the trapezoid the twin times moves with
/// (<see cref="TwinMotion.TrapezoidSeconds"/>: ramps at the acceleration up to the speed, or a triangle), stretched to the move's
/// actual duration when a turn at v_ori or \T makes it longer.
/// </summary>
internal sealed class RapidTriggProfile(double metres, double speed, double acceleration, double seconds)
{
    private readonly double _plain = TwinMotion.TrapezoidSeconds(metres, speed, acceleration);

    /// <summary>The length (m) of each ramp of the trapezoid (half the move when it is a triangle).</summary>
    private readonly double _ramp = Math.Min(speed * speed / (2 * acceleration), metres / 2);

    /// <summary>The seconds each ramp takes in the plain trapezoid.</summary>
    private double RampSeconds => Math.Sqrt(2 * _ramp / acceleration);

    /// <summary>The move's length in metres.</summary>
    public double Metres => metres;

    /// <summary>The move's duration in seconds.</summary>
    public double Seconds => seconds;

    /// <summary>The seconds after the start at which the TCP is <paramref name="along"/> metres along the move.</summary>
    public double TimeAt(double along)
    {
        if (metres <= 0 || _plain <= 0)
        {
            return along < metres ? 0 : seconds;
        }
        along = Math.Clamp(along, 0, metres);
        double ramp = _ramp, rampSeconds = RampSeconds;
        double t = along <= ramp ? Math.Sqrt(2 * along / acceleration)
            : along <= metres - ramp ? rampSeconds + (along - ramp) / speed
            : _plain - Math.Sqrt(2 * (metres - along) / acceleration);
        return t * seconds / _plain;
    }

    /// <summary>The TCP's speed (m/s) <paramref name="time"/> seconds after the start: up the ramp, at the speed, down the ramp.</summary>
    public double SpeedAt(double time)
    {
        if (metres <= 0 || seconds <= 0 || _plain <= 0)
        {
            return 0;
        }
        double t = Math.Clamp(time, 0, seconds) * _plain / seconds;
        double rampSeconds = RampSeconds;
        double v = t <= rampSeconds ? acceleration * t : t <= _plain - rampSeconds ? speed : acceleration * (_plain - t);
        return Math.Max(0, v) * _plain / seconds;
    }

    /// <summary>
    /// The seconds after the start at which the speed is sampled along the ramps: <paramref name="steps"/> points up the first ramp,
    /// the start of the last ramp and <paramref name="steps"/> points down it, the last one where the TCP stops.
    /// </summary>
    public IEnumerable<double> RampTimes(int steps)
    {
        if (metres <= 0 || seconds <= 0 || _plain <= 0)
        {
            yield return seconds;
            yield break;
        }
        double rampSeconds = RampSeconds, scale = seconds / _plain;
        for (int i = 1; i <= steps; i++)
        {
            yield return rampSeconds * i / steps * scale;
        }
        for (int i = 0; i <= steps; i++)
        {
            yield return i == steps ? seconds : (_plain - rampSeconds + rampSeconds * i / steps) * scale;
        }
    }

    /// <summary>The fraction of the move's length the TCP covered <paramref name="time"/> seconds after the start.</summary>
    public double FractionAt(double time)
    {
        if (metres <= 0 || seconds <= 0)
        {
            return time <= 0 ? 0 : 1;
        }
        double t = Math.Clamp(time, 0, seconds) * _plain / seconds;
        double ramp = _ramp, rampSeconds = RampSeconds;
        double along = t <= rampSeconds ? acceleration * t * t / 2
            : t <= _plain - rampSeconds ? ramp + (t - rampSeconds) * speed
            : metres - acceleration * (_plain - t) * (_plain - t) / 2;
        return Math.Clamp(along / metres, 0, 1);
    }
}
