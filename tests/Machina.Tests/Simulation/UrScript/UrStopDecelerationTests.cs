using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// stopj(a) and stopl(a, aRot) decelerate (the Script Manual: "decelerate joint speeds to zero", a the leading axis'
/// acceleration; "decelerate tool speed to zero", a the tool's, aRot its turn's). An asynchronous motion is stopped as ur_rtde
/// and UR's client library stop it: its thread is killed, then stopj/stopl is called. The arm goes on from the speeds it had
/// and stops v²/(2a) further on (per joint for stopj, along the tool's line for stopl), and the call returns only when it
/// stands. The motions run in real time on a manual clock that only the test moves: no wall time is measured.
/// </summary>
public sealed class UrStopDecelerationTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);
    private static readonly Joints Start = new(0, -90, 90, -90, -90, 0);
    private const double Degrees = 180 / Math.PI;

    /// <summary>
    /// movej of joint 1 by 1 rad and joint 2 by 0.5 rad (a = 1.4, v = 1.05), killed 0.2 s in: joint 1 is at 0.028 rad and turns
    /// at 0.28 rad/s, joint 2 at half of both. stopj(0.5): joint 1 leads and stops 0.28² / (2 · 0.5) = 0.0784 rad further on in
    /// 0.56 s; joint 2 stops with it, half as far (its own v² / 2a with a in proportion, 0.25 rad/s²).
    /// </summary>
    [Fact]
    public void Stopj_AfterTheMotionsThreadIsKilled_DeceleratesEachJointToRestAndReturnsThen()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def stopping():
              q = get_actual_joint_positions()
              global target = [q[0] + 1.0, q[1] + 0.5, q[2], q[3], q[4], q[5]]
              thread mover():
                movej(target, a=1.4, v=1.05)
              end
              t = run mover()
              sleep(0.2)
              kill t
              stopj(0.5)
              textmsg("stopped")
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the movej did not start: {twin.State} {twin.Error}");

        clock.Advance(TimeSpan.FromSeconds(0.2)); // the sleep ends: kill, then stopj
        UrMotion stop = StopMotion(twin, clock, 0.56);
        Joints atCall = twin.JointsNow(); // the clock stands where stopj was called: the stop's start
        Assert.Equal(0.5 * 1.4 * 0.2 * 0.2, (atCall.J1 - Start.J1) / Degrees, 6); // where the killed movej had brought it: no jump back
        Assert.Equal(0.5 * 0.7 * 0.2 * 0.2, (atCall.J2 - Start.J2) / Degrees, 6);

        clock.Advance(stop.Duration - TimeSpan.FromMilliseconds(20));
        Assert.DoesNotContain("stopped", twin.Pendant.Lines); // still slowing down: stopj has not returned
        Assert.Same(stop, twin.Motion);
        clock.Advance(TimeSpan.FromMilliseconds(40));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);
        Assert.Contains("stopped", twin.Pendant.Lines);

        Joints end = twin.Arm.Joints;
        double v1 = 1.4 * 0.2, v2 = 0.7 * 0.2, a1 = 0.5, a2 = 0.5 * v2 / v1; // joint 2 slows in proportion: both stop together
        Assert.Equal(v1 * v1 / (2 * a1), (end.J1 - atCall.J1) / Degrees, 4);
        Assert.Equal(v2 * v2 / (2 * a2), (end.J2 - atCall.J2) / Degrees, 4);
        Assert.Equal(atCall.J3, end.J3, 6); // the joints that stood still stay
        Assert.Equal(atCall.J6, end.J6, 6);
        Assert.Null(twin.Motion);
    }

    /// <summary>
    /// movel 100 mm up (a = 1.2, v = 0.25), killed 0.1 s in: the tool is 6 mm up and rises at 0.12 m/s. stopl(0.5) stops it
    /// 0.12² / (2 · 0.5) = 14.4 mm further up the same line, in 0.24 s.
    /// </summary>
    [Fact]
    public void Stopl_AfterTheMotionsThreadIsKilled_DeceleratesAlongTheToolsLine()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Pose start = twin.Arm.Tcp;
        Assert.True(twin.Start(Program("p[0, 0, 0.1, 0, 0, 0]", "stopl(0.5)")), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the movel did not start: {twin.State} {twin.Error}");

        clock.Advance(TimeSpan.FromSeconds(0.1));
        UrMotion stop = StopMotion(twin, clock, 0.24);
        Pose atCall = twin.Arm.FlangeAt(twin.JointsNow()) * twin.Arm.ToolCenter;
        Assert.Equal(0.5 * 1.2 * 0.1 * 0.1 * 1000, atCall.Position.Z - start.Position.Z, 2);

        clock.Advance(stop.Duration - TimeSpan.FromMilliseconds(20));
        Assert.DoesNotContain("stopped", twin.Pendant.Lines);
        clock.Advance(TimeSpan.FromMilliseconds(40));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);

        Pose end = twin.Arm.Tcp;
        Assert.Equal(0.12 * 0.12 / (2 * 0.5) * 1000, end.Position.Z - atCall.Position.Z, 1); // mm
        Assert.Equal(atCall.Position.X, end.Position.X, 1); // on the same line
        Assert.Equal(atCall.Position.Y, end.Position.Y, 1);
    }

    /// <summary>
    /// The e-Series' aRot: movel 100 mm up while turning 0.5 rad about the tool's axis, killed 0.1 s in: it rises at 0.12 m/s and
    /// turns at 0.6 rad/s. stopl(0.5, aRot=1.0): the turn leads (0.6 s against 0.24 s), so the tool rises 0.12 · 0.6 / 2 = 36 mm
    /// more and turns 0.6 · 0.6 / 2 = 0.18 rad more; without aRot the turn would slow at 0.5 rad/s² and take twice as long.
    /// </summary>
    [Fact]
    public void Stopl_WithARotationalAcceleration_TheLeadingTurnSetsTheStop()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start(Program("p[0, 0, 0.1, 0, 0, 0]", "stopl(0.5, aRot=1.0)", turn: 0.5)), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the movel did not start: {twin.State} {twin.Error}");

        clock.Advance(TimeSpan.FromSeconds(0.1));
        UrMotion stop = StopMotion(twin, clock, 0.6);
        Pose atCall = twin.Arm.FlangeAt(twin.JointsNow()) * twin.Arm.ToolCenter;
        clock.Advance(stop.Duration + TimeSpan.FromMilliseconds(20));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.True(twin.State == UrProgramState.Finished, twin.Error);

        Pose end = twin.Arm.Tcp;
        Assert.Equal(36, end.Position.Z - atCall.Position.Z, 1);
        RotationVector turn = (end.Rotation * atCall.Rotation.Inverse()).ToRotationVector();
        double turned = Math.Sqrt(turn.X * turn.X + turn.Y * turn.Y + turn.Z * turn.Z) / Degrees;
        Assert.Equal(0.18, turned, 3);
    }

    /// <summary>
    /// A killed motion that no stop takes over stops where it is when the program ends (a UR's program that ends without stopj
    /// stops suddenly), not back where the motion started.
    /// </summary>
    [Fact]
    public void KilledMotion_WithoutAStop_StandsWhereTheProgramsEndFoundIt()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true, StartJoints = Start });
        Assert.True(twin.Start("""
            def ending():
              q = get_actual_joint_positions()
              global target = [q[0] + 1.0, q[1], q[2], q[3], q[4], q[5]]
              thread mover():
                movej(target, a=1.4, v=1.05)
              end
              t = run mover()
              sleep(0.2)
              kill t
            end
            """), twin.Error);
        Assert.True(SpinWait.SpinUntil(() => twin.Motion is not null && clock.PendingTimers == 2, Bound), $"the movej did not start: {twin.State} {twin.Error}");
        clock.Advance(TimeSpan.FromSeconds(0.2));
        Assert.True(twin.WaitForEnd(Bound), "the program did not end");
        Assert.Null(twin.Motion);
        Assert.Equal(0.5 * 1.4 * 0.2 * 0.2, (twin.Arm.Joints.J1 - Start.J1) / Degrees, 6);
    }

    /// <summary>stopj while the arm stands (its own motion ended) returns at once and moves nothing.</summary>
    [Fact]
    public void Stopj_WhileTheArmStands_ReturnsAtOnce()
    {
        using var twin = new UrTwinController(new UrTwinOptions { StartJoints = Start });
        Assert.Equal(UrProgramState.Finished, twin.Run("def s():\n  stopj(2)\n  stopl(1, aRot=2)\n  textmsg(\"done\")\nend\n"));
        Assert.Equal(Start, twin.Arm.Joints);
        Assert.Equal(UrProgramState.Failed, twin.Run("def s():\n  stopl(1, aRot=0)\nend\n"));
        Assert.Contains("aRot", twin.Error);
    }

    /// <summary>A program that moves the tool along <paramref name="move"/> (base frame, turning <paramref name="turn"/> rad about its own z) in a thread it kills 0.1 s in, then runs <paramref name="stop"/>.</summary>
    private static string Program(string move, string stop, double turn = 0) => $$"""
        def stopping():
          p = get_actual_tcp_pose()
          global target = pose_add(pose_trans(p, p[0, 0, 0, 0, 0, {{turn.ToString(System.Globalization.CultureInfo.InvariantCulture)}}]), {{move}})
          thread mover():
            movel(target, a=1.2, v=0.25)
          end
          t = run mover()
          sleep(0.1)
          kill t
          {{stop}}
          textmsg("stopped")
        end
        """;

    /// <summary>Waits until the stop's slow-down of about <paramref name="seconds"/> is the motion in progress and its wait is set on the clock.</summary>
    private static UrMotion StopMotion(UrTwinController twin, ManualClock clock, double seconds)
    {
        UrMotion? stop = null;
        Assert.True(SpinWait.SpinUntil(() => (stop = twin.Motion) is { } m && Math.Abs(m.Duration.TotalSeconds - seconds) < 2e-3
            && clock.HasTimerDueIn(TimeSpan.FromMilliseconds(Math.Floor(m.Duration.TotalMilliseconds))), Bound),
            $"the stop did not start: {twin.Motion?.Duration} {twin.State} {twin.Error}");
        return stop!;
    }
}
