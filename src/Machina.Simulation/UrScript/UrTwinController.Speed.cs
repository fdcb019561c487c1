using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// <c>speedj(qd, a, t)</c> and <c>speedl(xd, a, t, aRot)</c> (the Script Manual: "Accelerate linearly in joint space and continue
/// with constant joint speed. The time t is optional; if provided the function will return after time t, regardless of the
/// target speed has been reached. If the time t is not provided, the function will return when the target speed is reached").
/// The arm's speed changes evenly from the speeds it has to the ones asked (the leading joint at a) and then stays: the motion
/// goes on after the call returned, until a motion or stop of the same thread takes it over (<c>stopj</c> slows it from that
/// speed), a hold or the program's end stops it where it is, or a joint reaches its position limit, where the arm stops with a
/// protective stop (the safety system's joint position limit).
/// </summary>
internal sealed partial class UrTwinController
{
    /// <summary>The control step of a UR (500 Hz): a speed command takes at least one.</summary>
    private const double ControlStep = 0.002;

    /// <summary>The runtime error of a motion commanded while another thread's motion is in progress (a UR's message).</summary>
    internal const string AnotherThread = "Another thread is already controlling the robot.";

    private ITimer? _speedTimer;

    /// <summary>
    /// Starts a speed motion towards the joint <paramref name="speeds"/> (degrees per second), the speeds changing evenly from
    /// the ones the arm has over <paramref name="ramp"/> seconds (0: at once), and returns after <paramref name="seconds"/> (0:
    /// when the speed is reached, at least one control step), the arm still moving. <paramref name="cancellation"/> is the
    /// calling thread's: it owns the motion.
    /// </summary>
    /// <exception cref="TwinMotionException">Another, live thread's motion is in progress.</exception>
    public void Speed(double[] speeds, double ramp, double seconds, int line, string function, CancellationToken cancellation)
    {
        WaitWhileHeld(cancellation);
        bool moving = TakeCoast(cancellation, false, out Joints at, out Joints before, out Joints after, out double step);
        double[] start = new double[6];
        if (moving)
        {
            double[] a = before.ToArray(), b = after.ToArray();
            for (int i = 0; i < 6; i++)
            {
                start[i] = (b[i] - a[i]) / step;
            }
        }
        else
        {
            at = Arm.Joints;
        }
        double wait = seconds > 0 ? seconds : Math.Max(ramp, ControlStep);
        if (!Clock.RealTime)
        {
            // Program time (a verification): the arm is where the speed brought it when the call returns, and stands there.
            var path = new UrSpeedPath(at, start, speeds, ramp, Arm.Model.MinJoints.ToArray(), Arm.Model.MaxJoints.ToArray());
            Arm.MoveTo(path.At(Math.Min(wait, path.LimitSeconds)), wait, line, function, cancellation);
            return;
        }
        var way = new UrSpeedPath(at, start, speeds, ramp, Arm.Model.MinJoints.ToArray(), Arm.Model.MaxJoints.ToArray());
        double duration = double.IsFinite(way.LimitSeconds) ? way.LimitSeconds : ramp;
        if (duration <= 0)
        {
            Clock.Wait(wait, cancellation); // at rest and asked to stay so: nothing moves
            return;
        }
        var motion = new UrMotion(at, way.At(duration), 0, Options.Time.GetTimestamp(), duration, 0, way.Over(duration), ownProfile: true) { OpenEnded = true };
        CancellationToken hold;
        lock (_holdGate)
        {
            hold = _holdStop.Token;
            _motion = motion;
            _motionOwner = cancellation;
            if (double.IsFinite(way.LimitSeconds))
            {
                int joint = way.LimitJoint;
                _speedTimer = Options.Time.CreateTimer(_ => AtJointLimit(motion, joint), null, TimeSpan.FromSeconds(duration), Timeout.InfiniteTimeSpan);
            }
        }
        StateChanged?.Invoke();
        using var both = CancellationTokenSource.CreateLinkedTokenSource(cancellation, hold);
        try
        {
            Clock.Wait(wait, both.Token);
        }
        catch (OperationCanceledException) when (!cancellation.IsCancellationRequested)
        {
            WaitWhileHeld(cancellation); // held: the hold stopped the arm; the call returns once the program goes on
        }
        Arm.Record(line, TwinTraceKind.Motion, function, way.At(Math.Min(wait, duration)));
    }

    /// <summary>A speed motion reached a joint's position limit (on the timer's thread): the arm stops there with a protective stop.</summary>
    private void AtJointLimit(UrMotion motion, int joint)
    {
        lock (_holdGate)
        {
            if (!ReferenceEquals(_motion, motion))
            {
                return;
            }
        }
        Pendant.Log($"Protective stop: joint {joint + 1} position limit violated");
        RequestProtectiveStop(); // the hold takes the motion: the arm stands at the limit
        TakeCoast(CancellationToken.None, true, out _, out _, out _, out _); // held already (another stop): stop the arm all the same
    }

    /// <summary>Stops the joint-limit timer of the speed motion being taken over, if any.</summary>
    private void StopSpeedTimer()
    {
        ITimer? timer;
        lock (_holdGate)
        {
            (timer, _speedTimer) = (_speedTimer, null);
        }
        timer?.Dispose();
    }
}
