using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The RETRY limit (RAPID: RETRY, ResetRetryCount, ERR_EXCRTYMAX; the system parameter "No Of Retry", 4): a handler that retries a
/// statement more than 4 times without it getting past its error raises ERR_EXCRTYMAX inside the handler, and an error inside an
/// error handler goes to the system error handler (RAPID Reference Manual, "Error Recovery"): the task stops.
/// </summary>
public class RapidRetryLimitTests
{
    private static RapidTwinController Load(string main, string more = "")
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n  VAR num tries := 0;\n  VAR num d := 0;\n  VAR num x;\n{main}\n{more}\nENDMODULE\n"));
        return twin;
    }

    private const string Divide = """
          PROC Divide()
            x := 1 / d;
          ERROR
            tries := tries + 1;
            RETRY;
          ENDPROC
        """;

    [Fact]
    public void RetryingMoreThanFourTimes_GoesToTheSystemErrorHandler_TheCallersHandlerDoesNotTakeIt()
    {
        RapidTwinController twin = Load(
            """
              PROC main()
                Divide;
                TPWrite "not reached";
              ERROR
                TPWrite "main's handler took " \Num:=ERRNO;
                TRYNEXT;
              ENDPROC
            """,
            Divide);

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        // The error, then 4 RETRYs that fail again: the fifth RETRY is one too many, an error inside the handler.
        Assert.StartsWith("Execution error: line 13: the maximum number of retries (4) is exceeded: ", twin.Error);
        Assert.DoesNotContain(twin.Pendant.Lines, l => l.StartsWith("main's handler", StringComparison.Ordinal));
        Assert.Equal(5.0, twin.Task().Program.Globals["tries"].Value);
    }

    [Fact]
    public void AnErrorInsideAnErrorHandler_StopsTheTask_NoHandlerAboveTakesIt()
    {
        RapidTwinController twin = Load(
            """
              PROC main()
                Inner;
                TPWrite "not reached";
              ERROR
                TPWrite "main's handler took " \Num:=ERRNO;
                TRYNEXT;
              ENDPROC
              PROC Inner()
                x := 1 / d;
              ERROR
                TPWrite "Inner's handler";
                x := 2 / d;
                TRYNEXT;
              ENDPROC
            """);

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        Assert.Equal("Inner's handler", twin.Pendant.Lines[0]);
        Assert.DoesNotContain(twin.Pendant.Lines, l => l.StartsWith("main's handler", StringComparison.Ordinal));
        Assert.StartsWith("Execution error: line 16: division by zero", twin.Error);
    }

    [Fact]
    public void RaiseInsideAnErrorHandler_StillPassesTheErrorToTheCallersHandler()
    {
        RapidTwinController twin = Load(
            """
              PROC main()
                Inner;
                TPWrite "after";
              ERROR
                TPWrite "main's handler: ERR_DIVZERO " \Bool:=ERRNO = ERR_DIVZERO;
                TRYNEXT;
              ENDPROC
              PROC Inner()
                x := 1 / d;
              ERROR
                RAISE;
              ENDPROC
            """);

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["main's handler: ERR_DIVZERO TRUE", "after"], twin.Pendant.Lines);
    }

    [Fact]
    public void AnErrorInARoutineCalledFromAHandler_ThatRoutinesOwnHandlerTakesIt()
    {
        RapidTwinController twin = Load(
            """
              PROC main()
                x := 1 / d;
                TPWrite "after";
              ERROR
                Safe;
                TRYNEXT;
              ENDPROC
              PROC Safe()
                x := 3 / d;
              ERROR
                TPWrite "Safe's own handler";
                TRYNEXT;
              ENDPROC
            """);

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["Safe's own handler", "after"], twin.Pendant.Lines);
    }

    [Fact]
    public void RetryingMoreThanFourTimes_WithoutAHandlerAbove_StopsTheTaskWithItsMessage()
    {
        RapidTwinController twin = Load("  PROC main()\n    Divide;\n  ENDPROC", Divide);

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        Assert.StartsWith("Execution error: line 9: the maximum number of retries (4) is exceeded: ", twin.Error);
        Assert.Equal(5.0, twin.Task().Program.Globals["tries"].Value);
    }

    [Fact]
    public void ARetryThatGetsPastItsError_StartsTheCountAgain_AndResetRetryCountToo()
    {
        RapidTwinController twin = Load(
            """
              VAR num fixAt := 3;
              VAR bool reset := FALSE;
              PROC main()
                FOR i FROM 1 TO 3 DO
                  tries := 0;
                  d := 0;
                  x := 1 / d;
                  TPWrite "got past after " \Num:=tries;
                ENDFOR
                tries := 0;
                d := 0;
                fixAt := 9;
                reset := TRUE;
                x := 1 / d;
                TPWrite "with ResetRetryCount " \Num:=tries;
              ERROR
                tries := tries + 1;
                IF tries >= fixAt d := 1;
                IF reset ResetRetryCount;
                RETRY;
              ENDPROC
            """);

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["got past after 3", "got past after 3", "got past after 3", "with ResetRetryCount 9"], twin.Pendant.Lines);
    }
}
