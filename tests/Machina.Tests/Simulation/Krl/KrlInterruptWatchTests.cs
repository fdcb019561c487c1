using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The robot interpreter looks at the interrupt conditions again only after a write of data they read (or an input, or a computed
/// variable while a timer counts): an element written in a loop is seen before the next statement, a write of other data is not
/// looked at (the KUKA driver's FOR over a ring slot's 80 characters evaluated three conditions per character).
/// </summary>
public class KrlInterruptWatchTests
{
    private const string Data = "DEFDAT watch\n  DECL BOOL marks[5]\n  DECL BOOL other[5]\n  DECL INT order[5]\n  DECL INT hits = 0\nENDDAT\n";

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void ElementWrittenInALoop_TheInterruptOnItRunsBeforeTheNextStatement(bool timerCounts)
    {
        string source = $$"""
            DEF watch( )
              DECL INT i
              INTERRUPT DECL 20 WHEN marks[3] DO seen( )
              INTERRUPT ON 20
              $TIMER[1] = 0
              $TIMER_STOP[1] = {{(timerCounts ? "FALSE" : "TRUE")}}
              FOR i = 1 TO 5
                other[i] = TRUE
                order[i] = hits
                marks[i] = TRUE
                order[i] = order[i] * 10 + hits
              ENDFOR
              $TIMER_STOP[1] = TRUE
            END

            DEF seen( )
              hits = hits + 1
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("watch.src", source), ("watch.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(1, (int)twin.Modules["watch"].Data["hits"].Value);
        object[] order = ((KrlArrayValue)twin.Modules["watch"].Data["order"].Value).Items;
        // Before the write of marks[3] no interrupt ran (0), right after it the routine had run once (1), and never again (11).
        Assert.Equal([0, 0, 1, 11, 11], order.Select(o => (int)o));
    }
}
