using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// <c>servoj(q, a, v, t, lookahead_time, gain)</c> (the Script Manual: "Servoj can be used for online realtime control of joint
/// positions ... The function is blocking for time t"): the arm tracks the target from where it is at the speeds it has
/// (<see cref="UrServoWay"/>), trailing it as a UR's servo does, and goes on tracking it after the call returned until the same
/// thread's next command (the next <c>servoj</c> goes on from the arm's position and speeds then), a stop, a hold or the
/// program's end. The Script Manual's t is the "time where the command is controlling the robot": a thread that stops calling
/// (it sleeps, waits, ends its loop) leaves the arm without a command once t and <see cref="UrTwinOptions.ServoRunOut"/> are
/// over, and the arm stands where the servo had brought it, short of the target (a UR's servo "runs out of targets"). The
/// model's joint speed limits are checked on that way: what the arm would do, not the step between targets.
/// </summary>
internal sealed partial class UrTwinController
{
    /// <summary>The Script Manual's range of <c>lookahead_time</c>, seconds.</summary>
    internal const double LeastLookahead = 0.03, MostLookahead = 0.2;

    /// <summary>The Script Manual's range of <c>gain</c>.</summary>
    internal const double LeastGain = 100, MostGain = 2000;

    /// <summary>
    /// Tracks <paramref name="target"/> for <paramref name="seconds"/> with the servo's <paramref name="lookahead"/> and
    /// <paramref name="gain"/> (taken within the manual's ranges) and returns, the arm still tracking it. Outside real time
    /// (program time, <c>machina verify</c>) the arm is at the target when the call returns, as the path asked.
    /// </summary>
    /// <exception cref="TwinMotionException">The target is beyond a joint limit, the arm would move a joint faster than the model
    /// allows, or another, live thread's motion is in progress.</exception>
    public void Servo(Joints target, double seconds, double lookahead, double gain, int line, CancellationToken cancellation)
    {
        Arm.RequireWithinLimits(target);
        if (!Clock.RealTime)
        {
            SettleCoast(cancellation);
            RequireSpeeds((target - Arm.Joints).ToArray(), 1 / seconds);
            Move(target, seconds, 0, null, line, "servoj", cancellation);
            return;
        }
        double look = Math.Clamp(lookahead, LeastLookahead, MostLookahead), g = Math.Clamp(gain, LeastGain, MostGain);
        RunSpeed((at, before, after, step) =>
        {
            var way = new UrServoWay(at, JointSpeeds(before, after, step), target, look, g);
            RequireSpeeds(way.PeakSpeeds(), 1);
            // The command controls the arm for t (and the run-out's allowance): a thread that gives no new command by then
            // leaves the arm standing where the servo had brought it, short of a target it had not reached.
            return (way, Math.Min(way.Settles, seconds + Options.ServoRunOut.TotalSeconds));
        }, seconds, line, "servoj", cancellation);
    }

    /// <summary>Refuses <paramref name="values"/> times <paramref name="scale"/> (degrees per second) above the model's joint speed limits.</summary>
    private void RequireSpeeds(double[] values, double scale)
    {
        if (Arm.Model.MaxJointSpeeds is not { } max)
        {
            return;
        }
        double[] limit = max.ToArray();
        for (int i = 0; i < 6; i++)
        {
            double speed = Math.Abs(values[i]) * scale;
            if (speed > limit[i])
            {
                throw new TwinMotionException(FormattableString.Invariant(
                    $"joint {i + 1} would move at {speed:0.#} deg/s, above its maximum of {limit[i]:0.#} deg/s"));
            }
        }
    }
}
