using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Session 34 (perf54r, issue 45): only writes of persistent data an IPers order watches are counted for the orders and wake a
/// motion; writes of other persistent data (our driver's <c>machinaMotionId := r.id</c> before every move) are plain stores. The
/// traps run as before: after a write of the watched datum, of its component or element, and through a reference parameter.
/// </summary>
public class RapidPersWatchTests
{
    private static (RapidTwinController Twin, IReadOnlyList<string> Lines) Run(string module)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", module));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return (twin, twin.Pendant.Lines);
    }

    [Fact]
    public void WritesOfUnwatchedPersistentData_AreNotCounted_WhileTheWatchedDatumStillRaisesItsTrap()
    {
        (RapidTwinController twin, IReadOnlyList<string> lines) = Run(
            """
            MODULE T
            PERS bool stopRequest := FALSE;
            PERS num motionId := 0;
            PERS pos cursor := [0, 0, 0];
            VAR intnum stopped;
            PROC main()
              stopRequest := FALSE;
              CONNECT stopped WITH OnStop;
              IPers stopRequest, stopped;
              FOR i FROM 1 TO 50 DO
                motionId := i;
                cursor.x := i;
              ENDFOR
              TPWrite "moved " + ValToStr(motionId) + " " + ValToStr(cursor);
              stopRequest := TRUE;
              TPWrite "after the stop";
            ENDPROC
            TRAP OnStop
              TPWrite "trap " + ValToStr(stopRequest);
              stopRequest := FALSE;
            ENDTRAP
            ENDMODULE
            """);

        Assert.Equal(["moved 50 [50,0,0]", "trap TRUE", "after the stop"], lines);
        // stopRequest := TRUE and the trap's own stopRequest := FALSE: the 100 writes of motionId and cursor are not counted.
        Assert.Equal(2, twin.PersistentWrites);
    }

    [Fact]
    public void AWatchedElement_IsLookedAtAfterWritesOfItsArray_AndAWatchedNumAfterAWriteThroughAReferenceParameter()
    {
        (RapidTwinController twin, IReadOnlyList<string> lines) = Run(
            """
            MODULE T
            PERS num flags{3} := [0, 0, 0];
            PERS num level := 0;
            PERS num other := 0;
            VAR intnum flagChanged;
            VAR intnum levelChanged;
            PROC main()
              flags := [0, 0, 0];
              level := 0;
              CONNECT flagChanged WITH OnFlag;
              IPers flags{2}, flagChanged;
              CONNECT levelChanged WITH OnLevel;
              IPers level, levelChanged;
              flags{1} := 4;
              other := 9;
              TPWrite "after the first";
              flags := [4, 8, 0];
              TPWrite "after the array";
              SetLevel level;
              TPWrite "after the call";
            ENDPROC
            PROC SetLevel(INOUT num value)
              value := 3;
              TPWrite "in the call";
            ENDPROC
            TRAP OnFlag
              TPWrite "flag " + ValToStr(flags{2});
            ENDTRAP
            TRAP OnLevel
              TPWrite "level " + ValToStr(level);
            ENDTRAP
            ENDMODULE
            """);

        Assert.Equal(["after the first", "flag 8", "after the array", "level 3", "in the call", "after the call"], lines);
        // flags{1}, flags and level through the parameter; not other.
        Assert.Equal(3, twin.PersistentWrites);
    }
}
