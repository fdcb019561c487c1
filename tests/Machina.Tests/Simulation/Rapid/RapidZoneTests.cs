using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Zones on the RAPID twin (<see cref="BlendModel"/>): a MoveL with a zone returns to the program as the arm enters the zone (the
/// program pointer runs ahead), the next MoveL rounds the corner without a stop, <c>fine</c> stops, and a wait or the end of the
/// program lets the arm reach its last waypoint. The numbers are those of the UR square (UrBlendTests), worked in BlendModelTests.
/// </summary>
public class RapidZoneTests
{
    /// <summary>A 100 mm square from where the arm stands at 250 mm/s (1.2 m/s², set in the options) with <paramref name="zone"/> at each corner; CRobT after the first move.</summary>
    private static string Square(string zone, string between = "") => $"""
        MODULE T
          CONST speeddata s250 := [250, 500, 5000, 1000];
          VAR robtarget p0;
          VAR robtarget p;
          VAR robtarget here;
          PROC main()
            p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
            p := p0;
            p.trans.x := p0.trans.x + 100;
            MoveL p, s250, {zone}, tool0;
            here := CRobT(\Tool:=tool0 \WObj:=wobj0);
            TPWrite NumToStr(here.trans.x - p0.trans.x, 3);
            {between}
            p.trans.y := p0.trans.y + 100;
            MoveL p, s250, {zone}, tool0;
            p.trans.x := p0.trans.x;
            MoveL p, s250, {zone}, tool0;
            MoveL p0, s250, {zone}, tool0;
          ENDPROC
        ENDMODULE
        """;

    private static RapidTwinController Run(string module)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2 });
        twin.Load(("T.mod", module));
        Assert.Equal(RapidProgramState.Finished, twin.Run());
        return twin;
    }

    [Fact]
    public void SquareWithZ20_RoundsEveryCorner_ReturnsAtTheZone_AndEndsAtItsLastTarget()
    {
        RapidTwinController fine = Run(Square("fine"));
        RapidTwinController zoned = Run(Square("z20"));
        Pose start = new RapidTwinController().Arm.Tcp;

        // fine: four trapezoids of 0.1/0.25 + 0.25/1.2 s. z20 (pzone_tcp 20 mm): 0.425759 s to the first zone, three parabolas
        // and straight parts of 0.391305 s each, and the last zone to a stop at the start (0.182574 s).
        Assert.Equal(4 * (0.1 / 0.25 + 0.25 / 1.2), fine.Clock.Seconds, 4);
        Assert.Equal(0.425759 + 3 * 0.391305 + 0.182574, zoned.Clock.Seconds, 4);
        // The program pointer ran ahead: CRobT after the first MoveL reads the arm where it entered the 20 mm zone.
        Assert.Equal(["100"], fine.Pendant.Lines);
        Assert.Equal(["80"], zoned.Pendant.Lines);
        // The trace keeps the waypoints as programmed; the arm stands at the last one.
        Vector[] corners = [.. zoned.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Motion).Select(e => e.Tcp.Position - start.Position)];
        Assert.Equal(4, corners.Length);
        Vector[] expected = [new(100, 0, 0), new(100, 100, 0), new(0, 100, 0), new(0, 0, 0)];
        for (int i = 0; i < 4; i++)
        {
            Assert.InRange((corners[i] - expected[i]).Length, 0, 1e-6);
        }
        Assert.InRange((zoned.Arm.Tcp.Position - start.Position).Length, 0, 1e-6);
    }

    [Fact]
    public void AWaitTime_LetsTheArmStopAtItsWaypointFirst()
    {
        RapidTwinController twin = Run(Square("z20", "WaitTime 0.5;"));

        // The first corner is a stop (0.425759 s to the zone, 0.182574 s to stop in it, 0.5 s of wait); the other two are rounded
        // and the second side starts from rest: 0.425759 s to its zone, like the first.
        Assert.Equal(0.425759 + 0.182574 + 0.5 + 0.425759 + 2 * 0.391305 + 0.182574, twin.Clock.Seconds, 4);
    }

    [Fact]
    public void ZArgument_OverridesPzoneTcp()
    {
        RapidTwinController twin = Run(Square("z200 \\Z:=20"));

        Assert.Equal(["80"], twin.Pendant.Lines);
        Assert.Equal(0.425759 + 3 * 0.391305 + 0.182574, twin.Clock.Seconds, 4);
    }

    [Fact]
    public void AProgramWithASocket_StopsAtEveryTarget()
    {
        // Our driver streams over a socket: whether the next move has arrived in time is timing no test controls, so the twin does
        // not blend there (docs/simulation.md) and an acknowledged move means the arm reached its target.
        string module = Square("z20").Replace("PROC main()\n", "VAR socketdev s;\n  PROC main()\n    SocketCreate s;\n", StringComparison.Ordinal);
        Assert.Contains("SocketCreate s;", module, StringComparison.Ordinal);

        RapidTwinController twin = Run(module);

        Assert.Equal(["100"], twin.Pendant.Lines);
        Assert.Equal(4 * (0.1 / 0.25 + 0.25 / 1.2), twin.Clock.Seconds, 4);
    }

    [Fact]
    public async Task RealTime_TheArmRoundsTheCornerOnTheParabola()
    {
        var clock = new ManualClock();
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2, Time = clock, RealTime = true });
        twin.Load(("T.mod", Square("z20")));
        Pose start = twin.Arm.Tcp;
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        Task<RapidProgramState> run = Task.Run(() => twin.Run("main", stop.Token));
        TimeSpan bound = TimeSpan.FromMinutes(1);

        // The first MoveL waits on the clock's first timer (0.425759 s to its zone); the second MoveL starts on the clock's
        // second timer, from the zone's entry (80, 0) past the corner (100, 0) to (100, 20), then 60 mm straight on.
        Assert.True(SpinWait.SpinUntil(() => clock.TimersCreated == 1 && clock.PendingTimers == 1, bound), "the first MoveL did not start");
        // To the zone's entry exactly: advancing past it could fire the second MoveL's timer too, when the woken program set it
        // while the clock was still moving (seen once under load: "the second MoveL did not start").
        Assert.Equal(0.425, clock.AdvanceToNextTimer()!.Value.TotalSeconds, 6); // Task.Delay counts whole milliseconds
        Assert.True(SpinWait.SpinUntil(() => clock.TimersCreated == 2 && clock.PendingTimers == 1, bound), "the second MoveL did not start");
        double blend = BlendModel.Length(new Vector(0.08, 0, 0), new Vector(0.1, 0, 0), new Vector(0.1, 0.02, 0));
        clock.Advance(TimeSpan.FromSeconds(0.391305 * (blend / 2) / (blend + 0.06))); // half way along the parabola
        Vector half = twin.Arm.Tcp.Position - start.Position;

        while (!run.IsCompleted)
        {
            Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || clock.PendingTimers > 0, bound), "the program stalled");
            clock.Advance(TimeSpan.FromSeconds(1));
        }

        Assert.Equal(RapidProgramState.Finished, await run);
        // The parabola's middle: a quarter of the entry, half of the corner and a quarter of the exit, 7.07 mm inside the corner.
        Assert.InRange((half - new Vector(95, 5, 0)).Length, 0, 0.05);
        Assert.Equal(0.425759 + 3 * 0.391305 + 0.182574, twin.Clock.Seconds, 4);
        Assert.InRange((twin.Arm.Tcp.Position - start.Position).Length, 0, 1e-6);
    }
}
