namespace Machina;

/// <summary>
/// How fast a motion runs along its path: from a start speed up (or down) to a cruise speed at a constant acceleration, then to an
/// end speed, over a distance (any one unit of length or angle). Start and end at rest give the usual trapezoid; a blended motion
/// starts or ends at the speed it carries through a blend. The cycle-time estimate and the twins share it.
/// </summary>
internal readonly struct SpeedProfile
{
    private readonly double _start, _peak, _end, _acceleration, _rampUp, _cruise, _rampDown, _upDistance, _cruiseDistance;

    private SpeedProfile(double distance, double start, double peak, double end, double acceleration)
    {
        Distance = distance;
        _start = start;
        _peak = peak;
        _end = end;
        _acceleration = acceleration;
        _rampUp = Math.Abs(peak - start) / acceleration;
        _rampDown = Math.Abs(peak - end) / acceleration;
        _upDistance = Math.Abs(peak * peak - start * start) / (2 * acceleration);
        _cruiseDistance = distance - _upDistance - Math.Abs(peak * peak - end * end) / (2 * acceleration);
        _cruise = peak > 0 ? _cruiseDistance / peak : 0;
        Seconds = _rampUp + _cruise + _rampDown;
    }

    /// <summary>The length of the way.</summary>
    internal double Distance { get; }

    /// <summary>How long the way takes, in seconds.</summary>
    internal double Seconds { get; }

    /// <summary>
    /// The fastest way over <paramref name="distance"/> that starts at <paramref name="startSpeed"/>, never exceeds
    /// <paramref name="cruise"/> (unless it starts above it) and ends at <paramref name="endSpeed"/>, changing speed at
    /// <paramref name="acceleration"/> (0 or infinite: at once). When the distance is too short for the change of speed, the speed
    /// changes evenly over it.
    /// </summary>
    internal static SpeedProfile Plan(double distance, double startSpeed, double cruise, double endSpeed, double acceleration)
    {
        distance = Math.Max(0, distance);
        startSpeed = Math.Max(0, startSpeed);
        endSpeed = Math.Max(0, endSpeed);
        if (!(cruise > 0))
        {
            return new SpeedProfile(0, 0, 0, 0, 1);
        }
        if (!(acceleration > 0) || double.IsPositiveInfinity(acceleration))
        {
            return new SpeedProfile(distance, cruise, cruise, cruise, double.MaxValue);
        }
        double peak = startSpeed > cruise ? cruise // slowing down from a faster motion
            : Math.Min(cruise, Math.Sqrt((2 * acceleration * distance + startSpeed * startSpeed + endSpeed * endSpeed) / 2));
        double needed = (Math.Abs(peak * peak - startSpeed * startSpeed) + Math.Abs(peak * peak - endSpeed * endSpeed)) / (2 * acceleration);
        if (needed > distance * (1 + 1e-9) || peak <= 0)
        {
            // Too short to change speed at this acceleration: one even change from start to end speed.
            double mean = (startSpeed + endSpeed) / 2;
            if (!(mean > 0))
            {
                return new SpeedProfile(distance, cruise, cruise, cruise, double.MaxValue);
            }
            double seconds = distance / mean;
            double even = Math.Abs(endSpeed - startSpeed) / seconds;
            return even > 0 ? new SpeedProfile(distance, startSpeed, endSpeed, endSpeed, even) : new SpeedProfile(distance, startSpeed, startSpeed, startSpeed, double.MaxValue);
        }
        return new SpeedProfile(distance, startSpeed, peak, endSpeed, acceleration);
    }

    /// <summary>The distance covered <paramref name="seconds"/> after the start (0 before, the whole distance after the end).</summary>
    internal double DistanceAt(double seconds)
    {
        if (Distance <= 0 || seconds >= Seconds)
        {
            return Distance;
        }
        if (seconds <= 0)
        {
            return 0;
        }
        if (seconds < _rampUp)
        {
            double a = _peak >= _start ? _acceleration : -_acceleration;
            return _start * seconds + 0.5 * a * seconds * seconds;
        }
        if (seconds < _rampUp + _cruise)
        {
            return _upDistance + _peak * (seconds - _rampUp);
        }
        double t = seconds - _rampUp - _cruise;
        double down = _end >= _peak ? _acceleration : -_acceleration;
        return Math.Min(Distance, _upDistance + _cruiseDistance + _peak * t + 0.5 * down * t * t);
    }

    /// <summary>The speed <paramref name="seconds"/> after the start.</summary>
    internal double SpeedAt(double seconds)
    {
        if (seconds <= 0)
        {
            return _start;
        }
        if (seconds >= Seconds)
        {
            return _end;
        }
        if (seconds < _rampUp)
        {
            return _start + (_peak >= _start ? 1 : -1) * _acceleration * seconds;
        }
        if (seconds < _rampUp + _cruise)
        {
            return _peak;
        }
        return _peak + (_end >= _peak ? 1 : -1) * _acceleration * (seconds - _rampUp - _cruise);
    }
}
