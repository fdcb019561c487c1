using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Guards of session 32's shortcuts in the RAPID machine (issue 45): a num or bool stored into an element or a component without a
/// copy, NOT in a condition computed without a box, and the check for interrupts between statements made inline. The values, the
/// errors and the traps are what RAPID gives, as before.
/// </summary>
public class RapidScalarStoreTests
{
    private static IReadOnlyList<string> Lines(string module)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", module));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void NumsAndBoolsStoredIntoElementsAndComponents_AreThoseValues_AndAStringStillIsHeldTo80Characters()
    {
        IReadOnlyList<string> lines = Lines(
            """
            MODULE T
            PROC main()
              VAR num list{3} := [1, 2, 3];
              VAR bool flags{2};
              VAR pos p := [1, 2, 3];
              VAR pose frames{2};
              VAR string words{2};
              list{2} := 7.25;
              flags{2} := TRUE;
              p.y := -4.5;
              frames{2}.trans.z := 9;
              IF StrToVal("12.5", list{3}) TPWrite "converted";
              TPWrite ValToStr(list) + " " + ValToStr(flags) + " " + ValToStr(p) + " " + ValToStr(frames{2}.trans);
              words{1} := "abcdefghijabcdefghijabcdefghijabcdefghijabcdefghijabcdefghijabcdefghijabcdefghijab";
            ERROR
              TPWrite "error " \Num:=ERRNO;
              TPWrite "words " + words{1};
              TRYNEXT;
            ENDPROC
            ENDMODULE
            """);

        Assert.Equal(
            ["converted", "[1,7.25,12.5] [FALSE,TRUE] [1,-4.5,3] [0,0,9]", $"error {RapidErrorNumbers.StringTooLong}", "words "],
            lines);
    }

    [Fact]
    public void NotInACondition_NegatesItsOperand_AndRaisesNotPresForAnOptionalNotGiven()
    {
        IReadOnlyList<string> lines = Lines(
            """
            MODULE T
            PROC main()
              VAR num v;
              IF NOT StrToVal("x", v) TPWrite "not a number";
              IF NOT NOT StrToVal("3", v) TPWrite "three " \Num:=v;
              WHILE NOT v > 5 DO
                v := v + 2;
              ENDWHILE
              TPWrite "v " \Num:=v;
              Opt \Flag:=FALSE;
              Opt;
            ENDPROC
            PROC Opt(\bool Flag)
              IF NOT Present(Flag) TPWrite "absent";
              IF NOT Flag TPWrite "negated";
              TPWrite "given";
            ERROR
              TPWrite "notpres " + ValToStr(ERRNO = ERR_NOTPRES);
              TRYNEXT;
            ENDPROC
            ENDMODULE
            """);

        Assert.Equal(["not a number", "three 3", "v 7", "negated", "given", "absent", "notpres TRUE", "given"], lines);
    }

    [Fact]
    public void AnIPersTrap_RunsBeforeTheNextStatement_AfterAComponentWrite_AndNotAfterAnUnchangedValue()
    {
        IReadOnlyList<string> lines = Lines(
            """
            MODULE T
            PERS pos watched := [0, 0, 0];
            VAR intnum changed;
            PROC main()
              VAR num count := 0;
              watched := [0, 0, 0];
              CONNECT changed WITH OnWatched;
              IPers watched, changed;
              count := 1;
              TPWrite "before";
              watched.x := 5;
              TPWrite "after one";
              watched.x := 5;
              count := count + 1;
              TPWrite "after the same";
              watched := [5, 6, 0];
              TPWrite "after two";
              IDelete changed;
              watched.y := 7;
              TPWrite "after the delete";
            ENDPROC
            TRAP OnWatched
              TPWrite "trap " + ValToStr(watched);
            ENDTRAP
            ENDMODULE
            """);

        Assert.Equal(["before", "trap [5,0,0]", "after one", "after the same", "trap [5,6,0]", "after two", "after the delete"], lines);
    }
}
