using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// A WAIT FOR wakes when a variable its condition reads is written, by the other interpreter too (the submit interpreter sets a
/// global the robot program waits on), instead of looking again every interpreter cycle while a timer runs: an idle KUKA twin's
/// robot interpreter sleeps (issue 45, perf52q). Conditions that read a timer still look every cycle.
/// </summary>
public class KrlWaitWakeTests
{
    private const string SubmitData = "DEFDAT sps PUBLIC\n  DECL GLOBAL BOOL go = FALSE\n  DECL GLOBAL BOOL trig = FALSE\n  DECL GLOBAL BOOL release = FALSE\n  DECL GLOBAL INT turns = 0\nENDDAT\n";

    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(30);

    /// <summary>Runs <paramref name="robot"/> beside the submit program <paramref name="submit"/> (4 ms cycle) until the robot program ends.</summary>
    private static KrlProgramState RunBeside(KrlTwinController twin, string robot, string submit, Action? whileRunning = null)
    {
        twin.Load(("cell.src", robot), ("sps.sub", submit), ("sps.dat", SubmitData));
        using var stop = new CancellationTokenSource(Bound);
        Task submitting = Task.Factory.StartNew(() => twin.RunSubmit("sps", TimeSpan.FromMilliseconds(4), stop.Token), TaskCreationOptions.LongRunning);
        Task<KrlProgramState> running = Task.Factory.StartNew(() => twin.Run(cancellation: stop.Token), TaskCreationOptions.LongRunning);
        whileRunning?.Invoke();
        Assert.True(running.Wait(Bound), "the robot program did not end");
        stop.Cancel();
        Assert.True(submitting.Wait(Bound), "the submit interpreter did not stop");
        return running.Result;
    }

    [Fact]
    public void RobotWaitFor_AGlobalTheSubmitProgramSets_WhileATimerRuns_GoesOn()
    {
        const string robot = "DEF cell( )\n  $TIMER[1] = 0\n  $TIMER_STOP[1] = FALSE\n  WAIT FOR go\n  $TIMER_STOP[1] = TRUE\n  $OUT[1] = TRUE\nEND\n";
        const string submit = "DEF sps( )\n  turns = turns + 1\n  IF turns >= 3 THEN\n    go = TRUE\n  ENDIF\nEND\n";
        using var twin = new KrlTwinController();

        KrlProgramState state = RunBeside(twin, robot, submit);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.True(twin.Io.GetBit("$OUT", 0));
        Assert.True((int)twin.Modules["sps"].Data["turns"].Value >= 3);
    }

    [Fact]
    public void RobotWaitFor_AGlobal_LooksAgainOnlyWhenItIsWritten_NotEveryCycleOfTheRunningTimer()
    {
        // The robot waits while a timer runs; the submit program writes nothing the condition reads until the test releases it.
        // Before, the WAIT FOR looked again every interpreter cycle (12 ms; outside real-time mode at once, advancing the program
        // time a cycle each look): hundreds of looks in the 200 ms idle. Now it sleeps until the submit program's write wakes it.
        const string robot = "DEF cell( )\n  $TIMER[1] = 0\n  $TIMER_STOP[1] = FALSE\n  $OUT[2] = TRUE\n  WAIT FOR go\n  $TIMER_STOP[1] = TRUE\n  $OUT[1] = TRUE\nEND\n";
        const string submit = "DEF sps( )\n  IF release THEN\n    go = TRUE\n  ENDIF\nEND\n";
        using var twin = new KrlTwinController();
        long idleLooks = -1;

        KrlProgramState state = RunBeside(twin, robot, submit, () =>
        {
            Assert.True(SpinWait.SpinUntil(() => twin.Io.GetBit("$OUT", 1), Bound), "the robot program did not reach its WAIT FOR");
            Thread.Sleep(200);
            idleLooks = twin.WaitForLooks;
            twin.Modules["sps"].Data["release"].Value = true; // the submit program reads it at its next cycle and sets go
        });

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(0, idleLooks);
        Assert.Equal(1, twin.WaitForLooks);
        Assert.True(twin.Io.GetBit("$OUT", 0));
    }

    [Fact]
    public void RobotWaitFor_AnInterruptOnAGlobalTheSubmitProgramSets_RunsItsRoutine()
    {
        // The interrupt's condition reads a global the submit program sets: its write wakes the waiting WAIT FOR, which serves the
        // interrupt, whose routine sets what the WAIT FOR waits on. The submit program sets it once the interrupt is on ($OUT[2]):
        // an interrupt switched on while its condition is TRUE already waits for the next rising edge.
        const string robot = "DEF cell( )\n  INTERRUPT DECL 5 WHEN trig DO served( )\n  INTERRUPT ON 5\n  $TIMER_STOP[1] = FALSE\n  $OUT[2] = TRUE\n  WAIT FOR go\n  $TIMER_STOP[1] = TRUE\n  $OUT[1] = TRUE\nEND\nDEF served( )\n  $OUT[3] = TRUE\n  go = TRUE\nEND\n";
        const string submit = "DEF sps( )\n  IF $OUT[2] THEN\n    trig = TRUE\n  ENDIF\nEND\n";
        using var twin = new KrlTwinController();

        KrlProgramState state = RunBeside(twin, robot, submit);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.True(twin.Io.GetBit("$OUT", 2));
        Assert.True(twin.Io.GetBit("$OUT", 0));
    }

    [Fact]
    public void WaitFor_ATimer_StillLooksEveryInterpreterCycle()
    {
        // Outside real-time mode each look is a cycle of program time: the timer reaches 60 ms after five looks of 12 ms.
        const string robot = "DEF cell( )\n  $TIMER[1] = 0\n  $TIMER_STOP[1] = FALSE\n  WAIT FOR $TIMER[1] >= 60\n  $TIMER_STOP[1] = TRUE\n  $OUT[1] = TRUE\nEND\n";
        using var twin = new KrlTwinController();
        twin.Load(("cell.src", robot));
        using var stop = new CancellationTokenSource(Bound); // a timer condition taken for one woken on change would wait forever

        KrlProgramState state = twin.Run(cancellation: stop.Token);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(5, twin.WaitForLooks);
        Assert.True(twin.Io.GetBit("$OUT", 0));
    }

    [Fact]
    public void Conditions_AreMarkedWokenOnlyWhenEveryVariableTheyReadWakesAWaiter()
    {
        const string robot = """
            DEF cell( )
              DECL INT n
              WAIT FOR go AND $FLAG[2] AND $IN[n] AND NOT $STOPMESS
              WAIT FOR $TIMER[1] > 5
              WAIT FOR go OR ($OV_PRO > 50)
              INTERRUPT DECL 4 WHEN $TIMER_FLAG[1] DO cell( )
              INTERRUPT DECL 6 WHEN trig OR $FLAG[4] DO cell( )
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("cell.src", robot), ("sps.dat", SubmitData));
        List<KrlStmt> body = twin.Modules["cell"].Routines[0].Body;

        Assert.Equal([true, false, false], body.OfType<KrlWait>().Select(w => w.Woken));
        Assert.Equal([false, true], body.OfType<KrlInterruptDecl>().Select(i => i.Woken));
    }
}
