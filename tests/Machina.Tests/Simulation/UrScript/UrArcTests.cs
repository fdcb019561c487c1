using System.Globalization;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// movec on the real-time URScript twin: the tool centre point follows the circle from where it is through pose_via to pose_to on a
/// trapezoid of the tool speed v and acceleration a, the tool turning evenly to pose_to's orientation (mode 0); a held movec (a
/// protective stop or pause) stands on the circle and goes on along it; points that do not define a circle are refused.
/// </summary>
public class UrArcTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);
    private const double Speed = 0.1, Acceleration = 1.2;
    private static readonly double Length = 0.1 * Math.PI / 2; // m, the quarter circle

    /// <summary>A quarter circle of radius 100 mm from where the arm stands (centre 100 mm along -x), the tool turning 30° about its z axis.</summary>
    private static string QuarterCircle(double viaX = -0.029289321881, double viaY = 0.070710678119, int mode = 0) => string.Create(CultureInfo.InvariantCulture, $"""
        def arc():
          p0 = get_actual_tcp_pose()
          via = pose_add(p0, p[{viaX}, {viaY}, 0, 0, 0, 0])
          p1 = pose_trans(pose_add(p0, p[-0.1, 0.1, 0, 0, 0, 0]), p[0, 0, 0, 0, 0, 0.523598775598])
          movec(via, p1, a=1.2, v=0.1, mode={mode})
        end
        """);

    /// <summary>The part of a way of <paramref name="metres"/> done after <paramref name="t"/> s on a trapezoid from rest to rest at <see cref="Speed"/>, <see cref="Acceleration"/>.</summary>
    private static double Trapezoid(double metres, double t)
    {
        double ramp = Speed / Acceleration, total = metres / Speed + ramp;
        double s = t < ramp ? Acceleration * t * t / 2
            : t <= total - ramp ? Acceleration * ramp * ramp / 2 + Speed * (t - ramp)
            : metres - Acceleration * (total - t) * (total - t) / 2;
        return s / metres;
    }

    private static Pose Tcp(UrTwinController twin) => twin.Arm.Model.Kinematics.Forward(twin.JointsNow()) * twin.Arm.ToolCenter;

    private static (UrTwinController Twin, ManualClock Clock, Pose Start, ArcProbe Probe, UrMotion Motion) Start(int mode = 0)
    {
        var clock = new ManualClock();
        var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true });
        Pose start = twin.Arm.Tcp;
        Assert.True(twin.Start(QuarterCircle(mode: mode)), twin.Error);
        UrMotion? motion = null;
        Assert.True(SpinWait.SpinUntil(() => (motion = twin.Motion) is not null && clock.PendingTimers == 1, Bound), $"the movec did not start: {twin.State} {twin.Error}");
        return (twin, clock, start, new ArcProbe(start.Position + new Vector(-100, 0, 0), start.Position, start.Position + new Vector(-100, 100, 0)), motion!);
    }

    private static void AssertTurned(Pose start, Pose at, double fraction) =>
        Assert.True(Math.Abs(TwinRotation.AngleDegrees(start.Rotation, at.Rotation) - 30 * fraction) <= 0.5,
            FormattableString.Invariant($"at {fraction:P1} of the way the tool turned {TwinRotation.AngleDegrees(start.Rotation, at.Rotation):0.###}°, not {30 * fraction:0.###}°"));

    [Fact]
    public void Movec_RealTime_FollowsTheCircle_OnItsSpeedProfile()
    {
        (UrTwinController twin, ManualClock clock, Pose start, ArcProbe probe, UrMotion motion) = Start();
        using (twin)
        {
            double seconds = motion.Duration.TotalSeconds;
            Assert.Equal(Length / Speed + Speed / Acceleration, seconds, 6); // the arc's length, not the chords'

            foreach (double part in new[] { 0.25, 0.5, 0.75 })
            {
                clock.Advance(TimeSpan.FromSeconds(seconds * 0.25));
                double fraction = Trapezoid(Length, seconds * part); // 23.7 %, 50 %, 76.3 % of the way
                Pose at = Tcp(twin);
                probe.AssertAt(at.Position, 90 * fraction, $"movec at {part:P0} of its time");
                AssertTurned(start, at, fraction);
            }
            clock.Advance(TimeSpan.FromSeconds(seconds));
            Assert.True(twin.WaitForEnd(Bound));

            Assert.True(twin.State == UrProgramState.Finished, twin.Error);
            Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position + new Vector(-100, 100, 0)), 0, 1e-6);
            AssertTurned(start, twin.Arm.Tcp, 1);
            Assert.Equal(seconds, twin.Clock.Seconds, 4);
        }
    }

    [Fact]
    public void Movec_Held_StandsOnTheCircle_AndGoesOnAlongIt()
    {
        (UrTwinController twin, ManualClock clock, Pose start, ArcProbe probe, UrMotion motion) = Start();
        using (twin)
        {
            clock.Advance(motion.Duration / 2);
            Assert.True(twin.Hold());
            Assert.True(SpinWait.SpinUntil(() => twin.Motion is null, Bound), "the movec did not stop");
            probe.AssertAt(Tcp(twin).Position, 45, "held");
            clock.Advance(TimeSpan.FromSeconds(1));
            probe.AssertAt(Tcp(twin).Position, 45, "still held a second later");

            Assert.True(twin.Release()); // the rest of the arc, from rest, on its own trapezoid
            UrMotion? rest = null;
            Assert.True(SpinWait.SpinUntil(() => (rest = twin.Motion) is not null && clock.PendingTimers == 1, Bound), $"the movec did not go on: {twin.State} {twin.Error}");
            clock.Advance(rest!.Duration / 2);
            Pose at = Tcp(twin);
            probe.AssertAt(at.Position, 67.5, "half way through the rest");
            AssertTurned(start, at, 0.75);
            clock.Advance(rest.Duration);
            Assert.True(twin.WaitForEnd(Bound));

            Assert.True(twin.State == UrProgramState.Finished, twin.Error);
            Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position + new Vector(-100, 100, 0)), 0, 1e-6);
        }
    }

    [Fact]
    public void Movec_FixedMode_TurnsTheToolWithTheCircle_AndIgnoresTheTargetOrientation()
    {
        (UrTwinController twin, ManualClock clock, Pose start, ArcProbe probe, UrMotion motion) = Start(mode: 1);
        using (twin)
        {
            // The arc turns 90° counter-clockwise about the base z axis; mode 1 keeps the tool's orientation to its tangent, so
            // the tool turns with it (pose_to's extra 30° about the tool's z axis is not used).
            clock.Advance(motion.Duration / 2);
            Pose half = Tcp(twin);
            probe.AssertAt(half.Position, 45, "movec mode 1 half way");
            Assert.InRange(TwinRotation.AngleDegrees(half.Rotation, new Rotation(0, 0, 1, 45) * start.Rotation), 0, 0.5);
            clock.Advance(motion.Duration);
            Assert.True(twin.WaitForEnd(Bound));

            Assert.True(twin.State == UrProgramState.Finished, twin.Error);
            Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position + new Vector(-100, 100, 0)), 0, 1e-6);
            Assert.InRange(TwinRotation.AngleDegrees(twin.Arm.Tcp.Rotation, new Rotation(0, 0, 1, 90) * start.Rotation), 0, 1e-6);
        }
    }

    [Fact]
    public void Movec_WithAnUnknownMode_IsRefused()
    {
        using var twin = new UrTwinController();

        Assert.Equal(UrProgramState.Failed, twin.Run(QuarterCircle(mode: 2)));

        Assert.Equal("Runtime error: line 5: movec: argument 'mode' must be 0 (unconstrained) or 1 (fixed)", twin.Error);
    }

    [Theory]
    [InlineData(-0.05, 0.05)]        // on the chord from the start to pose_to
    [InlineData(0.00005, 0)]         // 0.05 mm from the start
    [InlineData(-0.1, 0.09995)]      // 0.05 mm from pose_to
    public void Movec_WhosePointsDoNotDefineACircle_IsRefused(double viaX, double viaY)
    {
        using var twin = new UrTwinController();
        Pose start = twin.Arm.Tcp;

        Assert.Equal(UrProgramState.Failed, twin.Run(QuarterCircle(viaX, viaY)));

        Assert.Equal("Runtime error: line 5: movec: the start, via and end points do not define a circle (two are closer than 0.1 mm, or all three are on one line)", twin.Error);
        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position), 0, 1e-9);
    }
}
