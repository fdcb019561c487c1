using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Approximate positioning on the KRL twin (<see cref="BlendModel"/>): a LIN with C_DIS returns to the program as the arm enters the
/// $APO.CDIS zone (the advance run), the next LIN rounds the corner, a LIN without it stops exactly, and $ADVANCE 0 or a WAIT SEC
/// let the arm reach the point first. The numbers are those of the UR square (UrBlendTests), worked in BlendModelTests.
/// </summary>
public class KrlApproximationTests
{
    /// <summary>A 100 mm square from where the arm stands at 0.25 m/s and 1.2 m/s², each LIN with <paramref name="approximation"/>.</summary>
    private static string Square(string approximation, string settings = "", string between = "") => $"""
        DEF prog( )
          DECL E6POS p0
          DECL E6POS p
          $VEL.CP = 0.25
          $ACC.CP = 1.2
          $APO.CDIS = 20
          {settings}
          PTP $AXIS_ACT
          p0 = $POS_ACT
          p = p0
          p.X = p0.X + 100
          LIN p {approximation}
          dx = $POS_ACT.X - p0.X
          {between}
          p.Y = p0.Y + 100
          LIN p {approximation}
          p.X = p0.X
          LIN p {approximation}
          LIN p0 {approximation}
        END
        """;

    private static KrlTwinController Run(string source)
    {
        var twin = new KrlTwinController();
        twin.Load([("prog.src", source), ("prog.dat", "DEFDAT prog\nDECL REAL dx\nENDDAT\n")]);
        KrlProgramState state = twin.Run();
        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    [Fact]
    public void SquareWithCDis_RoundsEveryCorner_AndEndsAtItsLastPoint()
    {
        KrlTwinController exact = Run(Square(""));
        KrlTwinController approximated = Run(Square("C_DIS"));
        Pose start = new KrlTwinController().Arm.Tcp;

        // Exact: four trapezoids of 0.1/0.25 + 0.25/1.2 s. C_DIS at 20 mm: 0.425759 s to the first zone, three parabolas and
        // straight parts of 0.391305 s each, and the last zone to a stop at the start (0.182574 s).
        Assert.Equal(4 * (0.1 / 0.25 + 0.25 / 1.2), exact.Clock.Seconds, 4);
        Assert.Equal(0.425759 + 3 * 0.391305 + 0.182574, approximated.Clock.Seconds, 4);
        Vector[] points = [.. approximated.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Motion).Skip(1).Select(e => e.Tcp.Position - start.Position)];
        Vector[] expected = [new(100, 0, 0), new(100, 100, 0), new(0, 100, 0), new(0, 0, 0)];
        Assert.Equal(4, points.Length);
        for (int i = 0; i < 4; i++)
        {
            Assert.InRange((points[i] - expected[i]).Length, 0, 1e-6);
        }
        Assert.InRange((approximated.Arm.Tcp.Position - start.Position).Length, 0, 1e-6);
    }

    [Fact]
    public void TheAdvanceRun_ReadsThePositionInTheZone_AndAdvanceZeroStopsExactly()
    {
        KrlTwinController approximated = Run(Square("C_DIS"));
        KrlTwinController noAdvance = Run(Square("C_DIS", "$ADVANCE = 0"));

        // $POS_ACT after the first LIN: where the arm entered the 20 mm zone, or at the point when nothing runs ahead.
        Assert.Equal(80, KrlValues.ToReal(approximated.Modules["prog"].Data["dx"].Value), 6);
        Assert.Equal(4 * (0.1 / 0.25 + 0.25 / 1.2), noAdvance.Clock.Seconds, 4);
    }

    [Fact]
    public void AWaitSec_EndsTheAdvanceRun_TheArmStopsAtThePointFirst()
    {
        KrlTwinController twin = Run(Square("C_DIS", between: "WAIT SEC 0.5"));

        // The first corner is a stop (0.425759 s to the zone, 0.182574 s to stop in it, then 0.5 s), the other two are rounded.
        Assert.Equal(0.425759 + 0.182574 + 0.5 + 0.425759 + 2 * 0.391305 + 0.182574, twin.Clock.Seconds, 4);
    }
}
