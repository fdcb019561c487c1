using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The RETRY limit (RAPID: RETRY, ResetRetryCount, ERR_EXCRTYMAX; the system parameter "No Of Retry", 4): a handler that retries a
/// statement more than 4 times without it getting past its error raises ERR_EXCRTYMAX to the caller, or stops the task.
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
    public void RetryingMoreThanFourTimes_RaisesErrExcrtymaxToTheCaller()
    {
        RapidTwinController twin = Load(
            """
              PROC main()
                Divide;
                TPWrite "not reached";
              ERROR
                TPWrite "main: ERR_EXCRTYMAX " \Bool:=ERRNO = ERR_EXCRTYMAX;
                TPWrite "handler runs " \Num:=tries;
              ENDPROC
            """,
            Divide);

        Assert.Equal(RapidProgramState.Finished, twin.Run());
        // The error, then 4 RETRYs that fail again: the fifth RETRY is one too many.
        Assert.Equal(["main: ERR_EXCRTYMAX TRUE", "handler runs 5"], twin.Pendant.Lines);
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
