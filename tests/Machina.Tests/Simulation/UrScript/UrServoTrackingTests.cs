using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// servoj as the Script Manual has it: the gain "works the same way as the P-term of a PID controller, where it adjusts the
/// current position towards the desired (q)", and lookahead_time "is used to project the current position forward in time with
/// the current velocity". The arm tracks its target and trails it; the twin used to put the arm on each target at the end of the
/// call (no lag) and refused a target whose step from the arm, over t, was faster than a joint may turn, which stopped ur_rtde's
/// realtime_control_example whenever its servo thread had fallen a few steps behind. Real time on a manual clock that only the
/// test moves: no wall time is measured.
/// </summary>
public sealed class UrServoTrackingTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);
    private static readonly Joints Start = new(0, -90, 90, -90, -90, 0);
    private const double Degrees = 180 / Math.PI;

    /// <summary>
    /// One joint's position under the servo law q'' = gain (q* - q - lookahead q'), integrated in small steps (independent of
    /// the twin's closed form): targets[k] held for <paramref name="step"/> seconds each, from rest at 0.
    /// </summary>
    private static double Integrate(Func<int, double> targets, int steps, double step, double lookahead, double gain)
    {
        const int Sub = 2000;
        double q = 0, v = 0, h = step / Sub;
        for (int k = 0; k < steps; k++)
        {
            double target = targets(k);
            for (int n = 0; n < Sub; n++)
            {
                double a = gain * (target - q - lookahead * v);
                v += a * h;
                q += v * h;
            }
        }
        return q;
    }

    /// <summary>Lets the program run to its next wait (a timer set) and moves the clock to it, <paramref name="count"/> times.</summary>
    private static void Step(ManualClock clock, UrTwinController twin, int count)
    {
        for (int k = 0; k < count; k++)
        {
            Assert.True(SpinWait.SpinUntil(() => clock.PendingTimers > 0 || twin.State != UrProgramState.Running, Bound), "the program set no timer");
            Assert.True(twin.State == UrProgramState.Running, twin.Error);
            clock.AdvanceToNextTimer();
        }
    }

    /// <summary>
    /// 100 servoj steps of 0.01 s with joint 1's target rising 0.005 rad a step (0.5 rad/s), lookahead 0.1 s, gain 300: after
    /// them the arm trails the last target by about lookahead times the speed (minus half a step), exactly where the servo law
    /// puts it (the session 34 twin had the arm on each target). Then the program sleeps: no new command, and the last one
    /// controlled the arm only for its t (the Script Manual's "time where the command is controlling the robot"), so once t
    /// and the run-out allowance (20 ms) are over the arm stands where the servo had brought it, short of the last target, as
    /// a UR's does when its servo thread stops calling. The session 34 twin went on to the last target while the program slept.
    /// </summary>
    [Fact]
    public void Servoj_ARampOfTargets_TheArmTrailsItAsTheServoLawSays_ThenStandsWhenTheCallsStop()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def ramp():
              q = get_actual_joint_positions()
              i = 0
              while i < 100:
                i = i + 1
                servoj([q[0] + 0.005 * i, q[1], q[2], q[3], q[4], q[5]], t=0.01, lookahead_time=0.1, gain=300)
              end
              textmsg("ramped")
              sleep(5)
            end
            """), twin.Error);
        Step(clock, twin, 100);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("ramped"), Bound), $"the ramp did not end: {twin.State} {twin.Error}");

        double expected = Integrate(k => 0.005 * (k + 1), 100, 0.01, 0.1, 300);
        double at = (twin.JointsNow().J1 - Start.J1) / Degrees;
        Assert.Equal(expected, at, 4);
        Assert.InRange(0.5 - at, 0.04, 0.05); // about 0.1 s · 0.5 rad/s behind the last target, not on it
        Assert.Equal(Start.J2, twin.JointsNow().J2, 6); // the joints not asked to move stay

        clock.Advance(TimeSpan.FromSeconds(3)); // no new command: the servo ran out 0.01 + 0.02 s after the last call began
        double stood = Integrate(k => 0.005 * Math.Min(k + 1, 100), 102, 0.01, 0.1, 300); // 0.02 s more on the last target
        double now = (twin.JointsNow().J1 - Start.J1) / Degrees;
        Assert.Equal(stood, now, 4);
        Assert.InRange(0.5 - now, 0.03, 0.04); // still about 0.035 rad short of the last target, not on it
        Assert.Equal(0, twin.JointSpeedsNow().J1, 6);
    }

    /// <summary>
    /// A target 1.5 degrees from the arm at rest with t = 0.002 (a servo thread that fell a few steps behind its target stream
    /// gets such a step): the old twin refused it ("servoj: joint 3 would move at 745 deg/s, above its maximum of 180 deg/s"),
    /// as if the arm jumped there in one step. The arm tracks it: after the call it has barely moved; the program then sleeps,
    /// so the servo runs out 20 ms after the call's 2 ms and the arm stands there, a little on its way (the session 34 twin took
    /// it all the way to the target while the program slept).
    /// </summary>
    [Fact]
    public void Servoj_ATargetAStepAhead_IsTrackedNotRefused()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def behind():
              q = get_actual_joint_positions()
              servoj([q[0], q[1], q[2] + 0.026, q[3], q[4], q[5]], 0, 0, 0.002, 0.1, 300)
              textmsg("tracked")
              sleep(2)
            end
            """), twin.Error);
        Step(clock, twin, 1);
        Assert.True(SpinWait.SpinUntil(() => twin.Pendant.Lines.Contains("tracked") || twin.State != UrProgramState.Running, Bound), "the servoj did not return");
        Assert.True(twin.State == UrProgramState.Running, twin.Error);
        double moved = (twin.JointsNow().J3 - Start.J3) / Degrees;
        Assert.Equal(Integrate(_ => 0.026, 1, 0.002, 0.1, 300), moved, 7); // 0.5 · 300 · 0.026 · 0.002² at most: a few microradians
        Assert.True(moved < 0.0001, $"joint 3 moved {moved} rad in 2 ms");

        clock.Advance(TimeSpan.FromSeconds(1.5));
        double stood = (twin.JointsNow().J3 - Start.J3) / Degrees;
        Assert.Equal(Integrate(_ => 0.026, 11, 0.002, 0.1, 300), stood, 6); // 2 ms of the call and 20 ms of run-out
        Assert.InRange(stood, 0.001, 0.003); // on its way, far from the target 0.026 rad on
        Assert.Equal(0, twin.JointSpeedsNow().J3, 6);
    }

    /// <summary>
    /// A target 1 rad away with t = 1 s: the old twin took it (1 rad/s is below the limit of 180 deg/s) and moved there evenly;
    /// the servo (gain 300, lookahead 0.1 s) would turn the joint at about 5 rad/s on its way, so it is refused with the speed the
    /// arm would reach, and the arm stays.
    /// </summary>
    [Fact]
    public void Servoj_AFarTarget_IsRefusedByTheSpeedTheArmWouldReach()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def far():
              q = get_actual_joint_positions()
              servoj([q[0] + 1.0, q[1], q[2], q[3], q[4], q[5]], t=1.0)
            end
            """), twin.Error);
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.Equal(UrProgramState.Failed, twin.State);
        Assert.Contains("servoj: joint 1 would move at", twin.Error);
        Assert.Contains("above its maximum of 180 deg/s", twin.Error);
        Assert.Equal(Start.J1, twin.Arm.Joints.J1, 6);
    }

    /// <summary>In program time (a verification) servoj puts the arm on its target when the call returns, as before.</summary>
    [Fact]
    public void Servoj_InProgramTime_EndsOnTheTarget()
    {
        using var twin = new UrTwinController(new UrTwinOptions { StartJoints = Start });
        Assert.Equal(UrProgramState.Finished, twin.Run("""
            def verify():
              q = get_actual_joint_positions()
              servoj([q[0] + 0.001, q[1], q[2], q[3], q[4], q[5]], t=0.002)
            end
            """));
        Assert.Equal(Start.J1 + 0.001 * Degrees, twin.Arm.Joints.J1, 6);
    }
}
