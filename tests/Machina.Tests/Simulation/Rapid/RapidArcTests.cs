using System.Globalization;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// MoveC on the real-time RAPID twin: the tool centre point follows the circle through the start, the CirPoint and the ToPoint at
/// the programmed speed (its time follows the arc's length), the tool reoriented evenly relative to the circular path (RAPID
/// reference, MoveC); a held MoveC (StopMove) stands on the circle and goes on along it; points that do not define a circle are refused.
/// </summary>
public class RapidArcTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    /// <summary>A quarter circle of radius 100 mm from where the arm stands (centre 100 mm along -x, counter-clockwise about z), the tool ending at <paramref name="end"/>.</summary>
    private static string QuarterCircle(Rotation end, double viaX = -29.289321881, double viaY = 70.710678119) => string.Create(CultureInfo.InvariantCulture, $"""
        MODULE T
          CONST speeddata s100 := [100, 500, 5000, 1000];
          VAR robtarget p0;
          VAR robtarget via;
          VAR robtarget p1;
          PROC main()
            p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
            via := p0;
            via.trans.x := p0.trans.x + {viaX};
            via.trans.y := p0.trans.y + {viaY};
            p1 := p0;
            p1.trans.x := p0.trans.x - 100;
            p1.trans.y := p0.trans.y + 100;
            p1.rot := [{end.W:R}, {end.X:R}, {end.Y:R}, {end.Z:R}];
            MoveC via, p1, s100, fine, tool0;
          ENDPROC
        ENDMODULE
        """);

    /// <summary>Seconds of the quarter circle: 157.08 mm at 100 mm/s with 1.2 m/s² ramps (the chords through the CirPoint would give 1.614 s).</summary>
    private static readonly double Seconds = TwinMotion.TrapezoidSeconds(0.1 * Math.PI / 2, 0.1, 1.2);

    private static (RapidTwinController Twin, ManualClock Clock, Pose Start, Pose End, ArcProbe Probe, Task<RapidProgramState> Run) Start(CancellationToken stop)
    {
        var clock = new ManualClock();
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2, Time = clock, RealTime = true });
        Pose start = twin.Arm.Tcp;
        Rotation endRotation = new Rotation(1, 0, 0, 30) * start.Rotation; // tilted 30° about the base x axis
        var end = new Pose(start.Position + new Vector(-100, 100, 0), endRotation);
        twin.Load(("T.mod", QuarterCircle(endRotation)));
        Task<RapidProgramState> run = Task.Run(() => twin.Run("main", stop));
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || (clock.TimersCreated == 1 && clock.PendingTimers == 1), Bound), "the MoveC did not start");
        Assert.False(run.IsCompleted, twin.Error);
        return (twin, clock, start, end, new ArcProbe(start.Position + new Vector(-100, 0, 0), start.Position, end.Position), run);
    }

    private static async Task FinishAsync(RapidTwinController twin, ManualClock clock, Task<RapidProgramState> run)
    {
        while (!run.IsCompleted)
        {
            Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || clock.PendingTimers > 0, Bound), "the program stalled");
            clock.Advance(TimeSpan.FromSeconds(1));
        }
        Assert.True(await run == RapidProgramState.Finished, twin.Error);
    }

    /// <summary>
    /// The tool at <paramref name="fraction"/> of the arc is reoriented relative to the path: the path frame turned 90°·f about z, and
    /// in it the orientation turned evenly from the start's to the end's (the end's relative to the path is the end turned back 90°).
    /// </summary>
    private static void AssertOrientation(Pose start, Pose end, Pose at, double fraction)
    {
        Rotation endToPath = new Rotation(0, 0, 1, -90) * end.Rotation;
        Rotation expected = new Rotation(0, 0, 1, 90 * fraction) * KinematicChecks.Slerp(start.Rotation, endToPath, fraction);
        double off = TwinRotation.AngleDegrees(expected, at.Rotation);
        Assert.True(off <= 0.5, FormattableString.Invariant($"at {fraction:P0} the tool is {off:0.###}° off its orientation relative to the path"));
        // A turn evenly in the base frame would be elsewhere: the test tells the two apart.
        Assert.True(TwinRotation.AngleDegrees(KinematicChecks.Slerp(start.Rotation, end.Rotation, fraction), expected) > 2);
    }

    [Fact]
    public async Task MoveC_RealTime_FollowsTheCircle_AtTheProgrammedSpeed()
    {
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        (RapidTwinController twin, ManualClock clock, Pose start, Pose end, ArcProbe probe, Task<RapidProgramState> run) = Start(stop.Token);

        // RAPID moves at constant speed along the path in the twin: a quarter of the time is a quarter of the arc.
        foreach (double fraction in new[] { 0.25, 0.5, 0.75 })
        {
            clock.Advance(TimeSpan.FromSeconds(Seconds * 0.25));
            Pose at = twin.Arm.Tcp;
            probe.AssertAt(at.Position, 90 * fraction, $"MoveC at {fraction:P0}");
            AssertOrientation(start, end, at, fraction);
        }
        await FinishAsync(twin, clock, run);

        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, end.Position), 0, 1e-6);
        Assert.InRange(TwinRotation.AngleDegrees(twin.Arm.Tcp.Rotation, end.Rotation), 0, 1e-6);
        Assert.Equal(Seconds, twin.Clock.Seconds, 4);
    }

    [Fact]
    public async Task MoveC_Held_StandsOnTheCircle_AndGoesOnAlongIt()
    {
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        (RapidTwinController twin, ManualClock clock, Pose start, Pose end, ArcProbe probe, Task<RapidProgramState> run) = Start(stop.Token);

        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.25));
        Assert.True(twin.Arm.Hold()); // what StopMove does
        probe.AssertAt(twin.Arm.Tcp.Position, 22.5, "held");
        clock.Advance(TimeSpan.FromSeconds(1));
        probe.AssertAt(twin.Arm.Tcp.Position, 22.5, "still held a second later");
        Assert.True(twin.Arm.IsHeld);

        Assert.True(twin.Arm.Release()); // StartMove: the rest of the arc, three quarters of the time, from where it stood
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || (clock.TimersCreated == 2 && clock.PendingTimers == 1), Bound), "the MoveC did not go on");
        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.75 / 2));
        Pose half = twin.Arm.Tcp;
        probe.AssertAt(half.Position, 22.5 + 67.5 / 2, "half way through the rest");
        AssertOrientation(start, end, half, 0.625);
        await FinishAsync(twin, clock, run);

        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, end.Position), 0, 1e-6);
        Assert.Equal(Seconds, twin.Clock.Seconds, 4);
    }

    [Fact]
    public async Task MoveC_WithItsPathCleared_EndsOnTheCircle_WhereTheArmStands()
    {
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        (RapidTwinController twin, ManualClock clock, _, _, ArcProbe probe, Task<RapidProgramState> run) = Start(stop.Token);

        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.5));
        twin.Arm.ClearPath(); // what ClearPath does: the MoveC ends where the arm stands and the program goes on

        Assert.True(await run.WaitAsync(Bound) == RapidProgramState.Finished, twin.Error);
        probe.AssertAt(twin.Arm.Tcp.Position, 45, "cleared half way");
        Assert.Equal("MoveC (path cleared)", twin.Arm.Trace[^1].Text);
        Assert.Equal(Seconds * 0.5, twin.Clock.Seconds, 4);
    }

    [Theory]
    [InlineData(-50, 50)]          // on the chord from the start to the ToPoint
    [InlineData(0.05, 0)]          // 0.05 mm from the start
    [InlineData(-100, 100.05)]     // 0.05 mm from the ToPoint
    public void MoveC_WhosePointsDoNotDefineACircle_IsRefused(double viaX, double viaY)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2 });
        Pose start = twin.Arm.Tcp;
        twin.Load(("T.mod", QuarterCircle(start.Rotation, viaX, viaY)));

        Assert.Equal(RapidProgramState.Failed, twin.Run());

        Assert.Equal("Execution error: line 15: MoveC: the start point, CirPoint and ToPoint do not define a circle (two are closer than 0.1 mm, or all three are on one line) (task T_ROB1)",
            twin.Error);
        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position), 0, 1e-9);
    }
}
