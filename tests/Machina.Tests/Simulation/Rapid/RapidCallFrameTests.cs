using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Routine calls as RAPID defines them, where the twin saves work per call: a routine's frame serves its next call (locals start
/// again from their initial values, a by-reference slot never writes the previous call's data), and a record passed to an IN
/// parameter that the routine never writes is not copied, while every way a copy is still needed keeps it.
/// </summary>
public class RapidCallFrameTests
{
    private static IReadOnlyList<string> Lines(string body, string data)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void LocalsStartFromTheirInitialValues_AtEveryCall()
    {
        IReadOnlyList<string> lines = Lines(
            """
              Count;
              Count;
              Count;
            """,
            """
            PROC Count()
              VAR num n := 10;
              VAR pos p;
              VAR string s;
              n := n + 1;
              p.x := p.x + 1;
              s := s + "a";
              FOR i FROM 1 TO 2 DO
                n := n + i;
              ENDFOR
              TPWrite ValToStr(n) + " " + ValToStr(p) + " " + s;
            ENDPROC
            """);

        Assert.Equal(["14 [1,0,0] a", "14 [1,0,0] a", "14 [1,0,0] a"], lines);
    }

    [Fact]
    public void RecursiveCalls_KeepTheirOwnLocals()
    {
        IReadOnlyList<string> lines = Lines(
            """
              TPWrite "5! = " \Num:=Fact(5);
              Nest 3;
            """,
            """
            FUNC num Fact(num n)
              VAR num below;
              IF n <= 1 THEN
                RETURN 1;
              ENDIF
              below := Fact(n - 1);
              RETURN n * below;
            ENDFUNC
            PROC Nest(num depth)
              VAR num mine;
              mine := depth * 10;
              IF depth > 1 THEN
                Nest depth - 1;
              ENDIF
              TPWrite "depth " + ValToStr(depth) + " mine " + ValToStr(mine);
            ENDPROC
            """);

        Assert.Equal(["5! = 120", "depth 1 mine 10", "depth 2 mine 20", "depth 3 mine 30"], lines);
    }

    /// <summary>
    /// An INOUT parameter given a whole variable shares the caller's data; given an element it gets a cell of its own, written back.
    /// The calls alternate, so a frame that kept the caller's data in the slot would write the wrong variable.
    /// </summary>
    [Fact]
    public void ByReferenceAndWrittenBackArguments_Alternate_WithoutWritingThePreviousCallsData()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR num a := 1;
              VAR num b := 100;
              VAR num values{3} := [10, 20, 30];
              Twice a;
              Twice values{2};
              Twice b;
              Twice values{3};
              Twice a;
              TPWrite ValToStr(a) + " " + ValToStr(b) + " " + ValToStr(values);
            """,
            """
            PROC Twice(INOUT num x)
              x := 2 * x;
            ENDPROC
            """);

        Assert.Equal(["4 200 [10,40,60]"], lines);
    }

    [Fact]
    public void ACallThatEndedInAnError_LeavesTheNextCallFreshLocals()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR num r;
              r := Risky(0);
              r := Risky(2);
              TPWrite "r " \Num:=r;
            ERROR
              TPWrite "main took " \Num:=ERRNO;
              TRYNEXT;
            """,
            """
            FUNC num Risky(num d)
              VAR num kept := 1;
              kept := kept + 5;
              RETURN kept / d;
            ENDFUNC
            """);

        Assert.Equal(["main took " + RapidErrorNumbers.DivZero, "r 3"], lines);
    }

    [Fact]
    public void ACalleeThatWritesItsInRecordParameter_WritesItsOwnCopy()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR pos mine := [1, 2, 3];
              Change mine;
              Change mine;
              TPWrite "caller " + ValToStr(mine);
            """,
            """
            PROC Change(pos p)
              p.x := p.x + 10;
              TPWrite "callee " + ValToStr(p);
            ENDPROC
            """);

        Assert.Equal(["callee [11,2,3]", "callee [11,2,3]", "caller [1,2,3]"], lines);
    }

    [Fact]
    public void AnInRecordParameterPassedOnByReference_LeavesTheCallersRecord()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR pos mine := [1, 2, 3];
              PassOn mine;
              PassLate mine;
              PassToBuiltin mine;
              TPWrite "caller " + ValToStr(mine);
            """,
            """
            PROC PassOn(pos p)
              Bump p.y;
              TPWrite "on " + ValToStr(p);
            ENDPROC
            PROC PassLate(pos p)
              %"BumpPos"% p;
              TPWrite "late " + ValToStr(p);
            ENDPROC
            PROC PassToBuiltin(pos p)
              Incr p.z;
              TPWrite "builtin " + ValToStr(p);
            ENDPROC
            PROC Bump(INOUT num n)
              n := n + 100;
            ENDPROC
            PROC BumpPos(INOUT pos q)
              q.x := q.x + 1000;
            ENDPROC
            """);

        Assert.Equal(["on [1,102,3]", "late [1001,2,3]", "builtin [1,2,4]", "caller [1,2,3]"], lines);
    }

    /// <summary>A record read by the callee keeps the value it had at the call while the same data is written meanwhile.</summary>
    [Fact]
    public void AnInRecordParameter_KeepsTheValueOfTheCall_WhileItsDataIsWrittenMeanwhile()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR pos mine := [1, 2, 3];
              Both mine, mine;
              PassRef shared;
              PassRef mine;
              ReadThenCall mine, Grow(mine);
              TPWrite "caller " + ValToStr(mine) + " " + ValToStr(shared);
            """,
            """
            VAR pos shared := [7, 8, 9];
            PROC Both(pos readOnly, INOUT pos written)
              written.x := 50;
              TPWrite "both " + ValToStr(readOnly);
            ENDPROC
            PROC PassRef(INOUT pos q)
              Show q;
            ENDPROC
            PROC Show(pos p)
              shared.x := shared.x + 1;
              TPWrite "show " + ValToStr(p);
            ENDPROC
            FUNC num Grow(INOUT pos q)
              q.z := q.z * 2;
              RETURN q.z;
            ENDFUNC
            PROC ReadThenCall(pos p, num z)
              TPWrite "read " + ValToStr(p) + " " + ValToStr(z);
            ENDPROC
            """);

        Assert.Equal(["both [1,2,3]", "show [7,8,9]", "show [50,2,3]", "read [50,2,3] 6", "caller [50,2,6] [9,8,9]"], lines);
    }

    /// <summary>The parameter read without a copy is still a value: the routine's own copies of it (assigned, returned) are independent.</summary>
    [Fact]
    public void ARecordReadWithoutACopy_StaysIndependentOfWhatTheCalleeMakesOfIt()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR pos mine := [1, 2, 3];
              VAR pos back;
              Keep mine;
              back := Same(mine);
              back.x := 99;
              kept.y := 77;
              TPWrite ValToStr(mine) + " " + ValToStr(back) + " " + ValToStr(kept);
            """,
            """
            VAR pos kept;
            PROC Keep(pos p)
              kept := p;
            ENDPROC
            FUNC pos Same(pos p)
              RETURN p;
            ENDFUNC
            """);

        Assert.Equal(["[1,2,3] [99,2,3] [1,77,3]"], lines);
    }
}
