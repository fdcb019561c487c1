using System.Globalization;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// CIRC on the real-time KRL twin: the tool centre point follows the circle through the start, the auxiliary point and the end
/// point at $VEL.CP (its time follows the arc's length), the tool turning evenly from the start to the end orientation; a held CIRC
/// (BRAKE) stands on the circle and goes on along it; points that do not define a circle are refused.
/// </summary>
public class KrlArcTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    /// <summary>A quarter circle of radius 100 mm from where the arm stands (centre 100 mm along -X), the tool turning <paramref name="turn"/>° about Z (A).</summary>
    private static string QuarterCircle(double turn = 30, double viaX = -29.289321881, double viaY = 70.710678119) => string.Create(CultureInfo.InvariantCulture, $$"""
        DEF prog( )
          DECL E6POS p0
          DECL E6POS via
          DECL E6POS p1
          PTP $AXIS_ACT
          $VEL.CP = 0.1
          $ACC.CP = 1.2
          $VEL.ORI1 = 500
          $ACC.ORI1 = 1000
          p0 = $POS_ACT
          via = p0
          via.X = p0.X + {{viaX}}
          via.Y = p0.Y + {{viaY}}
          p1 = p0
          p1.X = p0.X - 100
          p1.Y = p0.Y + 100
          p1.A = p0.A + {{turn}}
          CIRC via, p1
        END
        """);

    /// <summary>Seconds of the quarter circle: 157.08 mm at 0.1 m/s with 1.2 m/s² ramps (the chords through the auxiliary point would give 1.614 s).</summary>
    private static readonly double Seconds = TwinMotion.TrapezoidSeconds(0.1 * Math.PI / 2, 0.1, 1.2);

    private static (KrlTwinController Twin, ManualClock Clock, Pose Start, ArcProbe Probe, Task<KrlProgramState> Run) Start(CancellationToken stop)
    {
        var clock = new ManualClock();
        var twin = new KrlTwinController(new KrlTwinOptions { Time = clock, RealTime = true });
        Pose start = twin.Arm.Tcp;
        twin.Load(("prog.src", QuarterCircle()));
        Task<KrlProgramState> run = Task.Factory.StartNew(() => twin.Run(cancellation: stop), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || (clock.TimersCreated == 1 && clock.PendingTimers == 1), Bound), "the CIRC did not start");
        Assert.False(run.IsCompleted, twin.Error);
        return (twin, clock, start, new ArcProbe(start.Position + new Vector(-100, 0, 0), start.Position, start.Position + new Vector(-100, 100, 0)), run);
    }

    private static async Task FinishAsync(KrlTwinController twin, ManualClock clock, Task<KrlProgramState> run)
    {
        while (!run.IsCompleted)
        {
            Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || clock.PendingTimers > 0, Bound), "the program stalled");
            clock.Advance(TimeSpan.FromSeconds(1));
        }
        Assert.True(await run == KrlProgramState.Finished, twin.Error);
    }

    private static void AssertTurned(Pose start, Pose at, double fraction) =>
        Assert.True(Math.Abs(TwinRotation.AngleDegrees(start.Rotation, at.Rotation) - 30 * fraction) <= 0.5,
            FormattableString.Invariant($"at {fraction:P0} the tool turned {TwinRotation.AngleDegrees(start.Rotation, at.Rotation):0.###}°, not {30 * fraction:0.###}°"));

    [Fact]
    public async Task Circ_RealTime_FollowsTheCircle_AtThePathSpeed()
    {
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        (KrlTwinController twin, ManualClock clock, Pose start, ArcProbe probe, Task<KrlProgramState> run) = Start(stop.Token);

        foreach (double fraction in new[] { 0.25, 0.5, 0.75 })
        {
            clock.Advance(TimeSpan.FromSeconds(Seconds * 0.25));
            Pose at = twin.Arm.Tcp;
            probe.AssertAt(at.Position, 90 * fraction, $"CIRC at {fraction:P0}");
            AssertTurned(start, at, fraction);
        }
        await FinishAsync(twin, clock, run);

        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position + new Vector(-100, 100, 0)), 0, 1e-6);
        AssertTurned(start, twin.Arm.Tcp, 1);
        Assert.Equal(Seconds, twin.Clock.Seconds, 4);
    }

    [Fact]
    public async Task Circ_Held_StandsOnTheCircle_AndGoesOnAlongIt()
    {
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        (KrlTwinController twin, ManualClock clock, Pose start, ArcProbe probe, Task<KrlProgramState> run) = Start(stop.Token);

        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.5));
        Assert.True(twin.Arm.Hold()); // what BRAKE does
        probe.AssertAt(twin.Arm.Tcp.Position, 45, "held");
        clock.Advance(TimeSpan.FromSeconds(1));
        probe.AssertAt(twin.Arm.Tcp.Position, 45, "still held a second later");

        Assert.True(twin.Arm.Release());
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || (clock.TimersCreated == 2 && clock.PendingTimers == 1), Bound), "the CIRC did not go on");
        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.5 / 2));
        Pose at = twin.Arm.Tcp;
        probe.AssertAt(at.Position, 67.5, "half way through the rest");
        AssertTurned(start, at, 0.75);
        await FinishAsync(twin, clock, run);

        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position + new Vector(-100, 100, 0)), 0, 1e-6);
        Assert.Equal(Seconds, twin.Clock.Seconds, 4);
    }

    [Fact]
    public async Task Circ_WokenByAnInterrupt_BrakesOnTheCircle_AndGoesOnAlongIt()
    {
        // $FLAG[4] calls caught( ) while the CIRC runs: the arm brakes where it is, the routine runs, the CIRC goes on along the circle.
        string program = QuarterCircle()
            .Replace("  PTP $AXIS_ACT\n", "  INTERRUPT DECL 30 WHEN $FLAG[4] DO caught( )\n  INTERRUPT ON 30\n  PTP $AXIS_ACT\n", StringComparison.Ordinal)
            + "\n\nDEF caught( )\n  $FLAG[4] = FALSE\n  BRAKE\n  braked = TRUE\nEND\n";
        Assert.Contains("INTERRUPT ON 30", program, StringComparison.Ordinal);
        var clock = new ManualClock();
        var twin = new KrlTwinController(new KrlTwinOptions { Time = clock, RealTime = true });
        Pose start = twin.Arm.Tcp;
        var probe = new ArcProbe(start.Position + new Vector(-100, 0, 0), start.Position, start.Position + new Vector(-100, 100, 0));
        twin.Load(("prog.src", program), ("prog.dat", "DEFDAT prog\nDECL BOOL braked=FALSE\nENDDAT\n"));
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        Task<KrlProgramState> run = Task.Factory.StartNew(() => twin.Run(cancellation: stop.Token), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || (clock.TimersCreated == 1 && clock.PendingTimers == 1), Bound), "the CIRC did not start");
        bool Braked() => (bool)twin.Modules["prog"].Data["braked"].Value;

        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.25));
        twin.SetFlag(4, true);
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || (Braked() && clock.PendingTimers == 1), Bound), $"the CIRC did not go on after the interrupt: {twin.Error}");
        probe.AssertAt(twin.Arm.Tcp.Position, 22.5, "braked");
        clock.Advance(TimeSpan.FromSeconds(Seconds * 0.75 / 2));
        probe.AssertAt(twin.Arm.Tcp.Position, 22.5 + 67.5 / 2, "half way through the rest");
        await FinishAsync(twin, clock, run);

        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position + new Vector(-100, 100, 0)), 0, 1e-6);
        Assert.Equal(Seconds, twin.Clock.Seconds, 4);
    }

    [Theory]
    [InlineData(-50, 50)]       // on the chord from the start to the end point
    [InlineData(0, 0.05)]       // 0.05 mm from the start
    [InlineData(-99.95, 100)]   // 0.05 mm from the end point
    public void Circ_WhosePointsDoNotDefineACircle_StopsTheProgramBeforeTheMotion(double viaX, double viaY)
    {
        var twin = new KrlTwinController();
        Pose start = twin.Arm.Tcp;
        twin.Load(("prog.src", QuarterCircle(0, viaX, viaY)));

        Assert.Equal(KrlProgramState.Failed, twin.Run());

        Assert.Equal("Circle not possible: CIRC: the start, auxiliary and end points do not define a circle (two are closer than 0.1 mm, or all three are on one line) (prog.src, line 18)",
            twin.Error);
        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position), 0, 1e-9);
        Assert.Equal(twin.Error, twin.Pendant.Lines[^1]);
    }
}
