using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A record of numbers, strings and bools (a flat type) and an array of them are copied by sharing their components' references
/// (issue 45): the copy must still be a value of its own, whichever side is written afterwards, in every way a copy is made
/// (assignment to global data, to an array element, to a routine's own record, an aggregate's item, an IN parameter).
/// </summary>
public class RapidFlatCopyTests
{
    private static IReadOnlyList<string> Run(string body, string data)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void FlatTypes_AreRecordsWithoutRecordComponents()
    {
        Assert.True(RapidTypes.Pos.Flat);
        Assert.True(RapidTypes.Speeddata.Flat);
        Assert.True(RapidTypes.Zonedata.Flat); // a bool among the numbers
        Assert.False(RapidTypes.Robtarget.Flat);
        Assert.False(RapidTypes.PoseType.Flat);
        Assert.False(RapidTypes.Num.Flat);
    }

    [Fact]
    public void FlatRecord_CopiedIntoGlobalsElementsAndLocals_StaysItsOwnValue()
    {
        IReadOnlyList<string> lines = Run(
            """
              g := src;
              g.id := 2;
              g.s1 := "g";
              buf{2} := g;
              buf{2}.p1 := 30;
              Take;
              TPWrite ValToStr(src) + " " + ValToStr(g) + " " + ValToStr(buf{2});
              Give [7, 8, "agg", src.p1];
              TPWrite ValToStr(buf{1}) + " " + ValToStr(src);
            """,
            """
            RECORD request
              num id;
              num code;
              string s1;
              num p1;
            ENDRECORD
            VAR request src := [1, 5, "a", 10];
            VAR request g;
            VAR request buf{3};
            PROC Take()
              VAR request r;
              r := buf{2};
              r.p1 := 40;
              r.s1 := "r";
              TPWrite ValToStr(r) + " " + ValToStr(buf{2});
            ENDPROC
            PROC Give(request q)
              buf{1} := q;
              buf{1}.code := 9;
              TPWrite ValToStr(q);
            ENDPROC
            """);

        Assert.Equal(
        [
            "[2,5,\"r\",40] [2,5,\"g\",30]",
            "[1,5,\"a\",10] [2,5,\"g\",10] [2,5,\"g\",30]",
            "[7,8,\"agg\",10]",
            "[7,9,\"agg\",10] [1,5,\"a\",10]",
        ], lines);
    }

    [Fact]
    public void ArrayOfNumbers_CopiedFromAConstant_StaysItsOwnValue_AndAnArrayOfRecordsIsCopiedDeeply()
    {
        IReadOnlyList<string> lines = Run(
            """
              values := NO_VALUES;
              values{2} := 5;
              TPWrite ValToStr(values) + " " + ValToStr(NO_VALUES);
              values := NO_VALUES;
              TPWrite ValToStr(values);
              b := a;
              b{1}.x := 9;
              a{2}.y := 8;
              TPWrite ValToStr(a) + " " + ValToStr(b);
              flags := [TRUE, FALSE];
              other := flags;
              other{1} := FALSE;
              TPWrite ValToStr(flags) + " " + ValToStr(other);
            """,
            """
            CONST num NO_VALUES{3} := [0, 0, 0];
            VAR num values{3};
            VAR pos a{2} := [[1, 2, 3], [4, 5, 6]];
            VAR pos b{2};
            VAR bool flags{2};
            VAR bool other{2};
            """);

        Assert.Equal(
        [
            "[0,5,0] [0,0,0]",
            "[0,0,0]",
            "[[1,2,3],[4,8,6]] [[9,2,3],[4,5,6]]",
            "[TRUE,FALSE] [FALSE,FALSE]",
        ], lines);
    }

    [Fact]
    public void ComponentAndElementOfAnAbsentOptionalParameter_RaiseErrNotPres_AndOfANameReadItsCell()
    {
        IReadOnlyList<string> lines = Run(
            """
              Show;
              Show \P:=[1, 2, 3], \A:=[4, 5];
            """,
            """
            VAR num sum;
            PROC Show(\pos P, \num A{*})
              sum := P.x + A{2};
              TPWrite "sum " + NumToStr(sum, 0);
              P.y := A{1};
              A{1} := P.z;
              TPWrite ValToStr(P) + " " + ValToStr(A);
            ERROR
              IF ERRNO = ERR_NOTPRES THEN
                TPWrite "not present";
                RETURN;
              ENDIF
            ENDPROC
            """);

        Assert.Equal(["not present", "sum 6", "[1,4,3] [3,5]"], lines);
    }
}
