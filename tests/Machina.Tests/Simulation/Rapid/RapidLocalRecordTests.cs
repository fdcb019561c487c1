using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A routine's own VAR record datum keeps its record (issue 45): a record assigned to it is copied into the record it holds, and a
/// PROC's or TRAP's record datum without an initial value is given its initial value again in place at the next call. The datum
/// still behaves as a value: it never shares its components with the data it was assigned from or to, a routine's next call
/// starts from the initial value, and a FUNC's returned record stays what it returned.
/// </summary>
public class RapidLocalRecordTests
{
    private static RapidTwinController Run(string body, string data)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin;
    }

    [Fact]
    public void AssignedRecord_IsACopy_BothWays_NestedComponentsToo()
    {
        IReadOnlyList<string> lines = Run(
            """
              Use;
              TPWrite ValToStr(g.trans) + " " + ValToStr(h.trans);
            """,
            """
            VAR pose g := [[1, 2, 3], [1, 0, 0, 0]];
            VAR pose h;
            PROC Use()
              VAR pose t;
              t := g;
              t.trans.x := 10;
              TPWrite ValToStr(t.trans) + " " + ValToStr(g.trans);
              h := t;
              t.trans.y := 20;
              t := t;
              TPWrite ValToStr(t.trans) + " " + ValToStr(h.trans);
            ENDPROC
            """).Pendant.Lines;

        Assert.Equal(["[10,2,3] [1,2,3]", "[10,20,3] [10,2,3]", "[1,2,3] [10,2,3]"], lines);
    }

    [Fact]
    public void ProcRecord_StartsFromItsInitialValue_AtEveryCall_AndWhatItGaveAwayStays()
    {
        IReadOnlyList<string> lines = Run(
            """
              Keep 1, TRUE;
              Keep 2, FALSE;
              Keep 3, FALSE;
              TPWrite "kept " + ValToStr(g);
            """,
            """
            VAR pos g;
            VAR pos source := [7, 8, 9];
            PROC Keep(num k, bool give)
              VAR pos t;
              VAR robtarget r;
              TPWrite ValToStr(t) + " " + ValToStr(r.trans) + " " + ValToStr(r.robconf);
              t := source;
              t.x := k;
              r.trans := t;
              r.robconf.cf1 := k;
              IF give THEN
                g := Same(t);
              ENDIF
            ENDPROC
            FUNC pos Same(pos p)
              RETURN p;
            ENDFUNC
            """).Pendant.Lines;

        Assert.Equal(
        [
            "[0,0,0] [0,0,0] [0,0,0,0]", "[0,0,0] [0,0,0] [0,0,0,0]", "[0,0,0] [0,0,0] [0,0,0,0]", "kept [1,8,9]",
        ], lines);
    }

    [Fact]
    public void FuncRecords_ReturnedTwiceInOneExpression_StayWhatEachCallReturned()
    {
        IReadOnlyList<string> lines = Run(
            """
              TPWrite ValToStr(Make(1) + Make(2));
              TPWrite ValToStr(Make(3) - Make(5));
            """,
            """
            VAR pos source := [100, 0, 0];
            FUNC pos Make(num k)
              VAR pos t;
              t := source;
              t.y := k;
              RETURN t;
            ENDFUNC
            """).Pendant.Lines;

        Assert.Equal(["[200,3,0]", "[0,-2,0]"], lines);
    }

    [Fact]
    public void RecordDatum_AssignedAtEveryCall_AllocatesNoRecord()
    {
        const string Data =
            """
            VAR robtarget source := [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
            VAR num sink;
            PROC WithRecord()
              VAR robtarget t;
              t := source;
              sink := t.trans.x;
            ENDPROC
            PROC WithNumber()
              VAR num t;
              t := source.trans.x;
              sink := t;
            ENDPROC
            """;
        long withRecord = AllocatedPerCall("WithRecord", Data), withNumber = AllocatedPerCall("WithNumber", Data);

        // A robtarget is five records (and their arrays, about 440 B): made twice per call before (the datum's initial value and
        // the copy assigned to it), now given in place.
        Assert.InRange(withRecord - withNumber, -16, 16);
    }

    private static long AllocatedPerCall(string routine, string data)
    {
        const int Calls = 400;
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{routine};\nFOR i FROM 1 TO {Calls} DO\n{routine};\nENDFOR\nENDPROC\nENDMODULE\n"));
        long before = GC.GetAllocatedBytesForCurrentThread();
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return (GC.GetAllocatedBytesForCurrentThread() - before) / Calls;
    }
}
