using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// Blend radii on the URScript twin (<see cref="BlendModel"/>): a blended linear motion returns to the program where the arm enters
/// the zone of its waypoint, the next one carries on from there without a stop, and the last one ends exactly at its waypoint.
/// </summary>
public class UrBlendTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    /// <summary>A 100 mm square at 0.25 m/s and 1.2 m/s² from where the arm stands, every corner with blend radius <paramref name="r"/> (m).</summary>
    private static string Square(double r) => FormattableString.Invariant($"""
        def square():
          p0 = get_actual_tcp_pose()
          movel(pose_add(p0, p[0.1, 0, 0, 0, 0, 0]), a=1.2, v=0.25, r={r})
          movel(pose_add(p0, p[0.1, 0.1, 0, 0, 0, 0]), a=1.2, v=0.25, r={r})
          movel(pose_add(p0, p[0, 0.1, 0, 0, 0, 0]), a=1.2, v=0.25, r={r})
          movel(p0, a=1.2, v=0.25, r={r})
        end
        """);

    [Fact]
    public void Square_WithBlends_IsShorterByWhatTheModelGives_AndEndsExactly()
    {
        using var plain = new UrTwinController();
        using var blended = new UrTwinController();
        Pose start = blended.Arm.Tcp;

        Assert.Equal(UrProgramState.Finished, plain.Run(Square(0)));
        Assert.Equal(UrProgramState.Finished, blended.Run(Square(0.02)));

        // Without blends: four trapezoids of 0.1/0.25 + 0.25/1.2 s. With 20 mm blends (worked in BlendModelTests): 0.425759 s to the
        // first zone, then three times the parabola (0.032451 m at 0.219089 m/s) and 60 mm at up to 0.25 m/s (0.391305 s each),
        // and the last zone to a stop at the start (0.182574 s).
        Assert.Equal(4 * (0.1 / 0.25 + 0.25 / 1.2), plain.Clock.Seconds, 4);
        Assert.Equal(0.425759 + 3 * 0.391305 + 0.182574, blended.Clock.Seconds, 4);
        Assert.Equal(0, (blended.Arm.Tcp.Position - start.Position).Length, 6);
        // The trace keeps each waypoint as programmed (what `verify` compares), though the arm passed within 20 mm of it.
        TwinTraceEntry[] motions = [.. blended.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Motion)];
        Assert.Equal(4, motions.Length);
        Vector[] corners = [new(100, 0, 0), new(100, 100, 0), new(0, 100, 0), Vector.Zero];
        for (int i = 0; i < 4; i++)
        {
            Assert.Equal(0, (motions[i].Tcp.Position - start.Position - corners[i]).Length, 6);
        }
    }

    [Fact]
    public void Square_RealTime_NeverStopsAtABlendedCorner()
    {
        var clock = new ManualClock();
        using var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        var speeds = new List<double>();
        var lengths = new List<double>();
        Assert.True(twin.Start(Square(0.02)), twin.Error);

        // Four motions and the last one's way from its zone to its waypoint: each waits on a timer of the clock (Task.Delay's, due
        // when the motion ends, to the millisecond below), which moves only here, and only once that timer is set.
        UrMotion? previous = null;
        for (int k = 0; k < 5; k++)
        {
            UrMotion? motion = null;
            Assert.True(SpinWait.SpinUntil(() => (motion = twin.Motion) is { } m && !ReferenceEquals(m, previous) && clock.PendingTimers == 1, Bound),
                $"motion {k + 1} did not start: {twin.State} {twin.Error}, {clock.Elapsed}");
            previous = motion;
            Vector before = Tcp(twin);
            clock.Advance(TimeSpan.FromMilliseconds(1));
            speeds.Add((Tcp(twin) - before).Length / 1000 / 0.001); // m/s over the motion's first millisecond
            lengths.Add(motion!.Duration.TotalSeconds);
            clock.Advance(motion.Duration - TimeSpan.FromMilliseconds(1));
        }
        Assert.True(twin.WaitForEnd(Bound));

        Assert.Equal(UrProgramState.Finished, twin.State);
        Assert.InRange(speeds[0], 0, 0.001); // from rest: 0.6 mm/s after 1 ms at 1.2 m/s²
        for (int k = 1; k < 5; k++)
        {
            Assert.InRange(speeds[k], 0.219089 * 0.98, 0.219089 * 1.02); // the zone's entry speed, carried through the corner
        }
        Assert.Equal(0.425759, lengths[0], 4);
        Assert.Equal(0.182574, lengths[4], 4);
    }

    [Fact]
    public void BlendedMotion_BeforeASleep_StopsAtItsWaypointFirst()
    {
        using var twin = new UrTwinController();
        Pose start = twin.Arm.Tcp;

        Assert.Equal(UrProgramState.Finished, twin.Run("""
            def m():
              p0 = get_actual_tcp_pose()
              movel(pose_add(p0, p[0.1, 0, 0, 0, 0, 0]), a=1.2, v=0.25, r=0.02)
              sleep(1)
              movel(p0, a=1.2, v=0.25, r=0)
            end
            """));

        TwinTraceEntry wait = Assert.Single(twin.Arm.Trace, e => e.Kind == TwinTraceKind.Wait);
        Assert.Equal(0, (wait.Tcp.Position - start.Position - new Vector(100, 0, 0)).Length, 6);
        Assert.Equal(0.425759 + 0.182574 + 1 + (0.1 / 0.25 + 0.25 / 1.2), twin.Clock.Seconds, 4);
    }

    [Fact]
    public void BlendRadius_AboveHalfTheMotions_IsLimitedToHalf()
    {
        using var half = new UrTwinController();
        using var above = new UrTwinController();
        using var none = new UrTwinController();

        Assert.Equal(UrProgramState.Finished, half.Run(Square(0.05)));
        Assert.Equal(UrProgramState.Finished, above.Run(Square(0.5)));
        Assert.Equal(UrProgramState.Finished, none.Run(Square(0)));

        Assert.Equal(half.Clock.Seconds, above.Clock.Seconds, 9);
        Assert.True(above.Clock.Seconds < none.Clock.Seconds - 0.5, $"{above.Clock.Seconds} s blended, {none.Clock.Seconds} s not");
        Assert.Equal(0, (above.Arm.Tcp.Position - none.Arm.Tcp.Position).Length, 6);
    }

    private static Vector Tcp(UrTwinController twin) => (twin.Arm.Model.Kinematics.Forward(twin.JointsNow()) * twin.Arm.ToolCenter).Position;
}
