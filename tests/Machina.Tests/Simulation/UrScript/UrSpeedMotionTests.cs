using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// speedj/speedl as the Script Manual has them ("Accelerate linearly in joint space and continue with constant joint speed. The
/// time t is optional; if provided the function will return after time t"): the arm keeps the speed after the call returned,
/// until a stop of the thread slows it, or a joint reaches its limit (a protective stop). And a motion commanded while another,
/// live thread's motion runs is a runtime error, as on a UR ("Another thread is already controlling the robot."). Real time on
/// a manual clock only the test moves: no wall time is measured.
/// </summary>
public sealed class UrSpeedMotionTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);
    private static readonly Joints Start = new(0, -90, 90, -90, -90, 0);
    private const double Degrees = 180 / Math.PI;

    /// <summary>
    /// speedj(0.2 rad/s on joint 1, a = 0.5, t = 0.8): the speed is reached after 0.4 s (0.04 rad), then held; the call returns
    /// at 0.8 s with joint 1 at 0.12 rad still turning at 0.2 rad/s. stopj(1.0) slows it from there: 0.2 s, 0.02 rad further on.
    /// </summary>
    [Fact]
    public void Speedj_WithTime_KeepsTheSpeedAfterItReturns_SoStopjSlowsItFromThere()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def speeding():
              speedj([0.2, 0, 0, 0, 0, 0], 0.5, 0.8)
              textmsg("returned")
              stopj(1.0)
              textmsg("stopped")
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the speedj did not start: {twin.State} {twin.Error}");
        UrMotion speed = twin.Motion!;
        Assert.True(speed.OpenEnded);

        clock.Advance(TimeSpan.FromSeconds(0.5));
        Assert.Equal(0.04 + 0.2 * 0.1, (twin.JointsNow().J1 - Start.J1) / Degrees, 6); // on the ramp, then at speed
        Assert.Equal(0.2, twin.JointSpeedsNow().J1 / Degrees, 3);
        Assert.DoesNotContain("returned", twin.Pendant.Lines);

        clock.Advance(TimeSpan.FromSeconds(0.3)); // speedj returns, the arm still turning; stopj takes it over
        UrMotion? stop = null;
        Assert.True(SpinWait.SpinUntil(() => (stop = twin.Motion) is { OpenEnded: false } && clock.PendingTimers == 1, Bound),
            $"the stop did not start: {twin.Motion?.Duration} {twin.State} {twin.Error}");
        Assert.Contains("returned", twin.Pendant.Lines);
        Assert.Equal(0.2, stop!.Duration.TotalSeconds, 3);
        Assert.Equal(0.12, (twin.JointsNow().J1 - Start.J1) / Degrees, 4);

        clock.Advance(TimeSpan.FromSeconds(0.25));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);
        Assert.Contains("stopped", twin.Pendant.Lines);
        Assert.Equal(0.14, (twin.Arm.Joints.J1 - Start.J1) / Degrees, 4);
        Assert.Equal(Start.J2, twin.Arm.Joints.J2, 6);
        Assert.Null(twin.Motion);
    }

    /// <summary>
    /// speedj without t returns once the speed is reached (0.1 s at a = 10), and the joint goes on turning while the thread sleeps;
    /// then the program reads where it is: get_actual_joint_positions sees the motion part-way.
    /// </summary>
    [Fact]
    public void Speedj_WithoutTime_ReturnsAtSpeed_AndTheArmMovesOnWhileTheThreadSleeps()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def speeding():
              speedj([0, 0, 0, 0, 0, 1.0], 10)
              sleep(0.5)
              q = get_actual_joint_positions()
              textmsg(q[5])
              stopj(10)
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the speedj did not start: {twin.State} {twin.Error}");
        Assert.True(clock.HasTimerDueIn(TimeSpan.FromMilliseconds(100)), "speedj without t waits until the speed is reached");
        clock.Advance(TimeSpan.FromSeconds(0.1));
        Assert.True(SpinWait.SpinUntil(() => clock.HasTimerDueIn(TimeSpan.FromMilliseconds(500)), Bound), "the sleep did not start");
        clock.Advance(TimeSpan.FromSeconds(0.5));
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is { OpenEnded: false }, Bound), $"the stop did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.2));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);
        Assert.Contains("0.55", twin.Pendant.Lines); // 0.05 rad on the ramp, 0.5 rad at speed
        Assert.Equal(0.55 + 0.05, twin.Arm.Joints.J6 / Degrees, 4); // and 1² / (2 · 10) to rest
    }

    /// <summary>
    /// A speed that runs a joint into its position limit (wrist 3 of a UR5e: 360 degrees) stops the arm there with a protective
    /// stop, as the safety system's joint position limit does: the program is held, the joint stands at the limit.
    /// </summary>
    [Fact]
    public void Speedj_IntoAJointLimit_StopsTheArmThereWithAProtectiveStop()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def speeding():
              speedj([0, 0, 0, 0, 0, 1.0], 10)
              sleep(100)
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the speedj did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.1));
        Assert.True(SpinWait.SpinUntil(() => clock.HasTimerDueIn(TimeSpan.FromSeconds(100)), Bound), "the sleep did not start");
        clock.Advance(TimeSpan.FromSeconds(6)); // 0.05 rad on the ramp, then 2π - 0.05 rad more take 6.23 s
        Assert.False(twin.IsHeld);
        clock.Advance(TimeSpan.FromSeconds(1));
        Assert.True(SpinWait.SpinUntil(() => twin.IsHeld, Bound), "no protective stop");
        Assert.Contains("Protective stop: joint 6 position limit violated", twin.Pendant.Lines);
        Assert.Null(twin.Motion);
        Assert.Equal(twin.Arm.Model.MaxJoints.J6, twin.JointsNow().J6, 5);
    }

    /// <summary>speedl: the tool moves up at 0.1 m/s (a = 1: 0.1 s to reach it) and keeps rising after the call returns at t = 0.3.</summary>
    [Fact]
    public void Speedl_WithTime_TheToolKeepsRisingAfterItReturns()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Pose start = twin.Arm.Tcp;
        Assert.True(twin.Start("""
            def speeding():
              speedl([0, 0, 0.1, 0, 0, 0], 1.0, 0.3)
              sleep(0.1)
              textmsg("slept")
              stopl(1.0)
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the speedl did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.3));
        // Two timers due in 0.1 s: the sleep's and the speed motion's own look ahead (session 33: speedl looks 0.1 s ahead at a
        // time), so the one due then is not enough to tell that the sleep started.
        Assert.True(SpinWait.SpinUntil(() => clock.PendingTimers == 2 && clock.HasTimerDueIn(TimeSpan.FromMilliseconds(100)), Bound), "the sleep did not start");
        clock.Advance(TimeSpan.FromSeconds(0.1));
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is { OpenEnded: false }, Bound), $"the stop did not start: {twin.State} {twin.Error}");
        Pose atStop = twin.Arm.FlangeAt(twin.JointsNow()) * twin.Arm.ToolCenter;
        Assert.Equal(1000 * (0.005 + 0.1 * 0.3), atStop.Position.Z - start.Position.Z, 0); // mm: the ramp, then 0.3 s at speed
        clock.Advance(TimeSpan.FromSeconds(0.2));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);
    }

    /// <summary>
    /// A motion from the main thread while a live thread's movej runs is refused with a UR's runtime error: the program stops
    /// with it (the twin used to run both motions at once on one arm).
    /// </summary>
    [Theory]
    [InlineData("movej(get_actual_joint_positions(), a=1.4, v=1.05)", "movej")]
    [InlineData("stopj(2)", "stopj")]
    [InlineData("speedj([0.1, 0, 0, 0, 0, 0], 1, 0.1)", "speedj")]
    public void AMotion_WhileAnotherLiveThreadControlsTheArm_IsARuntimeError(string motion, string function)
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start($$"""
            def conflict():
              q = get_actual_joint_positions()
              global target = [q[0] + 1.0, q[1], q[2], q[3], q[4], q[5]]
              thread mover():
                movej(target, a=1.4, v=1.05)
              end
              t = run mover()
              sleep(0.2)
              {{motion}}
              textmsg("both")
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the movej did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.2));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.Equal(UrProgramState.Failed, twin.State);
        Assert.Contains($"{function}: Another thread is already controlling the robot.", twin.Error);
        Assert.Contains("line 9", twin.Error);
        Assert.DoesNotContain("both", twin.Pendant.Lines);
    }

    /// <summary>
    /// RTDE's actual_q and actual_qd show the speed motion going on after speedj returned: 1 s after speedj([0.2, 0, …], 0.5,
    /// 0.4) started, joint 1 is 0.04 + 0.2 · 0.6 = 0.16 rad further and still turns at 0.2 rad/s (a 10 Hz recipe, one package
    /// per step of the manual clock; the values depend on the clock only).
    /// </summary>
    [Fact]
    public async Task Rtde_SeesTheArmMoveOnAtTheSpeed_AfterSpeedjReturned()
    {
        var clock = new ManualClock();
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { TimeProvider = clock });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        await client.SetupOutputsAsync(10, "timestamp", "actual_q", "actual_qd");
        Assert.True(await client.StartAsync());
        Dictionary<string, object> data = await client.ReadDataAsync();
        double start = ((double[])data["actual_q"])[0], startTime = (double)data["timestamp"]; // the clock stands until the test moves it
        Assert.True(controller.Twin.Start("def p():\n  speedj([0.2, 0, 0, 0, 0, 0], 0.5, 0.4)\n  textmsg(\"returned\")\n  sleep(100)\nend\n"), controller.Twin.Error);
        Assert.True(SpinWait.SpinUntil(() => controller.Twin.Motion is { OpenEnded: true }, Bound), $"the speedj did not start: {controller.Twin.Error}");

        var period = TimeSpan.FromMilliseconds(100);
        for (int i = 0; i < 10; i++)
        {
            await OnlineWait.UntilAsync(() => clock.HasTimerDueIn(period), "the sender to wait for its next package");
            clock.Advance(period);
        }
        // The package of the clock's last step (a start or state change sends one more in between: read up to it).
        for (int n = 0; n < 100 && (double)data["timestamp"] < startTime + 1.0 - 1e-6; n++)
        {
            data = await client.ReadDataAsync();
        }
        Assert.Equal(startTime + 1.0, (double)data["timestamp"], 6);
        // The program thread runs its textmsg after the speedj returned at 0.4 s; it may run after the package was read.
        Assert.True(SpinWait.SpinUntil(() => controller.Twin.Pendant.Lines.Contains("returned"), Bound), "speedj did not return");
        Assert.Equal(0.16, ((double[])data["actual_q"])[0] - start, 4);
        Assert.Equal(0.2, ((double[])data["actual_qd"])[0], 3);
        Assert.NotNull(controller.Twin.Motion);
    }
}
