using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// The way of <c>speedl</c> (the Script Manual: "Accelerate linearly in Cartesian space and continue with constant tool speed"):
/// the tool centre point's velocity changes evenly from the one it has to the one asked over the ramp, then stays, so the tool
/// goes on along its straight line (turning about a fixed axis) however long the motion lasts; the joints are those that put the
/// tool there, each solved near the arm's joints a moment before. The way is looked at ahead a piece at a time
/// (<see cref="Extend"/>, a tenth of a second at a time), each sample at most <see cref="MaxStepMm"/> of the tool's way or <see cref="MaxStepDegrees"/> of its
/// turn after the last: it ends where the tool's line leaves the arm's reach, a joint would have to jump (a singularity, or a
/// joint at its limit whose solution lies the other way round), and the arm stops there with a protective stop. Samples more
/// than <see cref="KeepSeconds"/> behind the latest time asked for are let go, so a speedl that runs for hours holds a second's.
/// </summary>
internal sealed class UrToolSpeedPath : IUrSpeedWay
{
    /// <summary>The longest step of the tool between two samples, mm.</summary>
    private const double MaxStepMm = 5;

    /// <summary>The largest turn of the tool between two samples, degrees.</summary>
    private const double MaxStepDegrees = 2;

    /// <summary>The largest joint change between two samples that is still a smooth way, degrees (a UR's joint moves at most ~3° a control step at full speed).</summary>
    private const double MaxJointStep = 20;

    /// <summary>
    /// How far <see cref="Extend"/> looks at least each time it has to look further, seconds (at least one sample): a stream of
    /// short <c>speedl</c> steps (500 Hz) solves little more than each step's own way.
    /// </summary>
    private const double PieceSeconds = 0.1;

    /// <summary>
    /// How far behind the latest time asked for (<see cref="At"/>) samples are kept, seconds: the motion is asked for now and a
    /// millisecond either side of it (its speeds), never for long ago, so older samples are let go (an open-ended speedl runs
    /// for hours).
    /// </summary>
    private const double KeepSeconds = 1;

    /// <summary>How many samples at least are let go at once (fewer copies of the list).</summary>
    private const int DropChunk = 64;

    private readonly Lock _gate = new();
    private readonly TwinArm _arm;
    private readonly Pose _start;
    private readonly Vector _v0, _v, _w0, _w; // mm/s and degrees per second, base frame
    private readonly double _ramp, _step;
    private readonly bool _constantAfterRamp;
    private readonly List<Joints> _samples; // _samples[k] at (_dropped + k) * _step seconds
    private int _dropped; // samples let go from the front: behind what can still be asked for
    private double _asked; // the latest time asked for
    private double _limit = double.PositiveInfinity;
    private string _reason = "";
    private bool _complete;

    /// <summary>
    /// The way from <paramref name="from"/> (the arm's joints), the tool moving at <paramref name="v0"/> (mm/s) and turning at
    /// <paramref name="w0"/> (degrees per second, base frame) there, towards <paramref name="v"/> and <paramref name="w"/> over
    /// <paramref name="ramp"/> seconds.
    /// </summary>
    public UrToolSpeedPath(TwinArm arm, Joints from, Vector v0, Vector w0, Vector v, Vector w, double ramp)
    {
        (_arm, _v0, _w0, _v, _w, _ramp) = (arm, v0, w0, v, w, ramp);
        _start = arm.FlangeAt(from) * arm.ToolCenter;
        double mm = Math.Max(v0.Length, v.Length), degrees = Math.Max(w0.Length, w.Length);
        _step = Math.Clamp(Math.Min(mm > 0 ? MaxStepMm / mm : 1, degrees > 0 ? MaxStepDegrees / degrees : 1), 0.002, 0.5);
        _constantAfterRamp = v.Length == 0 && w.Length == 0; // after the ramp the tool stands: known to the end once past it
        _samples = [from];
        if (_constantAfterRamp)
        {
            Extend(ramp);
        }
    }

    /// <inheritdoc/>
    public double LimitSeconds
    {
        get
        {
            lock (_gate)
            {
                return _limit;
            }
        }
    }

    /// <inheritdoc/>
    public string LimitReason
    {
        get
        {
            lock (_gate)
            {
                return _reason;
            }
        }
    }

    /// <inheritdoc/>
    public double KnownUntil
    {
        get
        {
            lock (_gate)
            {
                return _complete ? double.PositiveInfinity : LastIndex * _step;
            }
        }
    }

    /// <summary>The tool centre point <paramref name="t"/> seconds after the start (mm, base frame).</summary>
    public Pose PoseAt(double t)
    {
        Vector moved = Travel(_v0, _v, t), turned = Travel(_w0, _w, t);
        return new Pose(_start.Position + moved, Rotation.FromRotationVector(turned) * _start.Rotation);
    }

    /// <inheritdoc/>
    public void Extend(double seconds)
    {
        lock (_gate)
        {
            ExtendLocked(seconds);
        }
    }

    /// <inheritdoc/>
    public Joints At(double seconds)
    {
        lock (_gate)
        {
            double t = Math.Clamp(seconds, 0, _limit);
            ExtendLocked(t);
            if (t > _asked)
            {
                _asked = t;
                LetGo();
            }
            if (_complete && t >= LastIndex * _step)
            {
                return _samples[^1]; // past the ramp of a way that ends standing, or at its limit
            }
            int k = Math.Clamp((int)(t / _step) - _dropped, 0, _samples.Count - 1);
            return UrBuiltins.Near(_arm, PoseAt(t), _samples[k]);
        }
    }

    /// <summary>How many samples are held now (the way's memory).</summary>
    internal int HeldSamples
    {
        get
        {
            lock (_gate)
            {
                return _samples.Count;
            }
        }
    }

    /// <summary>The index (counted from the start) of the last sample.</summary>
    private int LastIndex => _dropped + _samples.Count - 1;

    /// <summary>Lets go of the samples more than <see cref="KeepSeconds"/> before the latest time asked for, the last one always kept (under the gate).</summary>
    private void LetGo()
    {
        int behind = Math.Min((int)((_asked - KeepSeconds) / _step) - _dropped, _samples.Count - 1);
        if (behind >= DropChunk)
        {
            _samples.RemoveRange(0, behind);
            _dropped += behind;
        }
    }

    /// <inheritdoc/>
    public IUrMotionPath Over(double duration) => new UrTimedSpeedPath(this, duration);

    /// <summary>The way a speed changing evenly from <paramref name="start"/> to <paramref name="end"/> over the ramp, then held, covers in <paramref name="t"/> seconds.</summary>
    private Vector Travel(Vector start, Vector end, double t)
    {
        if (t <= _ramp && _ramp > 0)
        {
            return start * t + (end - start) * (0.5 * t * t / _ramp);
        }
        return (start + end) * (0.5 * _ramp) + end * (t - _ramp);
    }

    /// <summary>Adds samples through <paramref name="seconds"/> (at least a piece of them), stopping at the way's limit (call under the gate).</summary>
    private void ExtendLocked(double seconds)
    {
        if (_complete || LastIndex * _step > seconds)
        {
            return;
        }
        int last = Math.Max((int)Math.Ceiling(seconds / _step), LastIndex + Math.Max(1, (int)Math.Ceiling(PieceSeconds / _step)));
        if (_constantAfterRamp)
        {
            last = (int)Math.Ceiling(_ramp / _step);
        }
        for (int k = LastIndex + 1; k <= last; k++)
        {
            if (!TrySample(k * _step, _samples[^1], out Joints next))
            {
                EndAt((k - 1) * _step, k * _step);
                return;
            }
            _samples.Add(next);
        }
        if (_constantAfterRamp)
        {
            _complete = true;
        }
    }

    /// <summary>The joints at <paramref name="t"/>, solved near <paramref name="near"/>; false when there are none that smooth (out of reach, a jump).</summary>
    private bool TrySample(double t, Joints near, out Joints joints)
    {
        try
        {
            joints = _arm.Solve(PoseAt(t), near);
        }
        catch (TwinMotionException)
        {
            joints = near;
            return false;
        }
        return UrGeometry.LargestChange(near, joints) <= MaxJointStep;
    }

    /// <summary>The way cannot go on between <paramref name="good"/> and <paramref name="bad"/> seconds: finds where (halving), and ends it there.</summary>
    private void EndAt(double good, double bad)
    {
        Joints at = _samples[^1];
        for (int n = 0; n < 40 && bad - good > 1e-6; n++)
        {
            double mid = 0.5 * (good + bad);
            if (TrySample(mid, at, out Joints joints))
            {
                (good, at) = (mid, joints);
            }
            else
            {
                bad = mid;
            }
        }
        _samples.Add(at);
        _limit = good;
        _complete = true;
        _reason = AtJointLimit(at) is int joint
            ? $"joint {joint + 1} position limit violated"
            : "speedl: the tool's straight line leaves the arm's reach (or passes a singularity)";
    }

    /// <summary>The joint that stands within a degree of its position limit at <paramref name="joints"/>, or null.</summary>
    private int? AtJointLimit(Joints joints)
    {
        double[] q = joints.ToArray(), min = _arm.Model.MinJoints.ToArray(), max = _arm.Model.MaxJoints.ToArray();
        for (int i = 0; i < 6; i++)
        {
            if (q[i] - min[i] < 1 || max[i] - q[i] < 1)
            {
                return i;
            }
        }
        return null;
    }
}
