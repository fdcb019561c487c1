using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// KRL's IO arrays ($IN, $OUT, $ANIN, $ANOUT) are the controller's <see cref="TwinIo"/> banks of the same names (issue 44: one IO
/// model for the three interpreters): what a program writes, by element, through an OUT parameter or through a configured
/// signal, is there for the host, and what the host sets there is what the program reads.
/// </summary>
public class KrlTwinIoTests
{
    [Fact]
    public void ProgramOutputs_AreTheTwinIoBanks_AndInputsSetThereAreWhatTheProgramReads()
    {
        const string source = """
            DEF prog( )
              $OUT[3] = TRUE
              $ANOUT[2] = 0.25
              Give($OUT[5])
              DO_Grip = TRUE
              IF $IN[1] THEN
                $OUT[9] = TRUE
              ENDIF
              IF $ANIN[1] > 0.5 THEN
                $OUT[10] = $OUT[3]
              ENDIF
            END

            DEF Give(b:OUT)
              DECL BOOL b
              b = TRUE
            END
            """;
        using var twin = new KrlTwinController(new KrlTwinOptions { Signals = [("DO_Grip", 12)] });
        twin.Load(("prog.src", source));
        twin.Io.SetBit("$IN", 0, true);
        twin.Io.SetNumber("$ANIN", 0, 0.75);

        Assert.True(twin.Run() == KrlProgramState.Finished, twin.Error);

        int[] on = [.. Enumerable.Range(0, twin.Io.Count("$OUT")).Where(i => twin.Io.GetBit("$OUT", i)).Select(i => i + 1)];
        Assert.Equal([3, 5, 9, 10, 12], on);
        Assert.Equal(0.25, twin.Io.GetNumber("$ANOUT", 1));
        Assert.Equal(0, twin.Io.GetNumber("$ANOUT", 0));
        Assert.Equal(
            ["$OUT[3] = TRUE", "$ANOUT[2] = 0.25", "$OUT[5] = TRUE", "DO_Grip = TRUE", "$OUT[9] = TRUE", "$OUT[10] = TRUE"],
            twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Output).Select(e => e.Text));
        // The program reads the arrays whole too: a copy of the bank.
        Assert.True((bool)((KrlArrayValue)twin.Environment.System["$OUT"].Value)[11]);
    }

    [Fact]
    public async Task AnInputTheHostSets_EndsAWaitFor()
    {
        const string source = """
            DEF prog( )
              $TIMER_STOP[1] = FALSE
              WAIT FOR $IN[2] OR ($TIMER[1] > 60000)
              IF $IN[2] THEN
                $OUT[1] = TRUE
              ENDIF
            END
            """;
        using var twin = new KrlTwinController(new KrlTwinOptions { RealTime = true });
        twin.Load(("prog.src", source));
        using var stop = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));
        long version = twin.InputsVersion;
        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || twin.State == KrlProgramState.Running, TimeSpan.FromSeconds(10)), "the program did not start");

        twin.SetInput(2, true);

        Assert.True(await run.WaitAsync(TimeSpan.FromSeconds(10)) == KrlProgramState.Finished, twin.Error);
        Assert.Equal(version + 1, twin.InputsVersion);
        Assert.True(twin.Io.GetBit("$IN", 1));
        Assert.True(twin.Io.GetBit("$OUT", 0));
    }

    [Fact]
    public void AnAnalogOutputOutsideMinusOneToOne_StopsTheProgram_WithTheControllersMessage()
    {
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", "DEF prog( )\n  $ANOUT[1] = 1.5\nEND\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.Contains("Value assignment inadmissible: $ANOUT takes values from -1 to 1", twin.Error);
    }
}
