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
        object[] order = ((KrlArrayValue)twin.Modules["watch"].Data["order"].Value).ToObjects();
        // Before the write of marks[3] no interrupt ran (0), right after it the routine had run once (1), and never again (11).
        Assert.Equal([0, 0, 1, 11, 11], order.Select(o => (int)o));
    }

    [Fact]
    public void ScalarAndComponentOfAWatchedVariableWritten_TheInterruptRunsBeforeTheNextStatement_OtherWritesDoNotRunIt()
    {
        const string Source = """
            DEF watch2( )
              DECL FRAME local
              INTERRUPT DECL 21 WHEN go DO seen( )
              INTERRUPT DECL 22 WHEN place.X > 5 DO seen( )
              INTERRUPT ON 21
              INTERRUPT ON 22
              quiet = 1
              local.X = 9
              trace[1] = hits
              go = TRUE
              trace[2] = hits
              quiet = 2
              place.Y = 9
              trace[3] = hits
              place.X = 9
              trace[4] = hits
              quiet = 3
              trace[5] = hits
            END

            DEF seen( )
              hits = hits + 1
            END
            """;
        const string Data2 = "DEFDAT watch2\n  DECL BOOL go = FALSE\n  DECL INT quiet = 0\n  DECL FRAME place = {X 0, Y 0, Z 0, A 0, B 0, C 0}\n  DECL INT trace[5]\n  DECL INT hits = 0\nENDDAT\n";
        using var twin = new KrlTwinController();
        twin.Load(("watch2.src", Source), ("watch2.dat", Data2));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        object[] trace = ((KrlArrayValue)twin.Modules["watch2"].Data["trace"].Value).ToObjects();
        // go written: the routine ran before trace[2]; place.Y does not make place.X > 5; place.X does, before trace[4]; once each.
        Assert.Equal([0, 1, 1, 2, 2], trace.Select(o => (int)o));
    }
}
