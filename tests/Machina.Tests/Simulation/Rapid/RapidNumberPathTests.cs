using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Expressions of numbers and conditions as the machine computes them without boxes (issue 45): the operators on nums inside other
/// operators, in IF and WHILE conditions, array indices, FOR bounds and local array sizes give the values and the errors RAPID gives
/// (the order of evaluation, AND/OR stopping at the left operand, ERR_DIVZERO, ERR_ARGVALERR for DIV/MOD of a fraction,
/// ERR_NUMOVERFLOW, ERR_OUTOFBND, ERR_NOTPRES), and the same expressions with a signal or a string take the general path.
/// </summary>
public class RapidNumberPathTests
{
    private static IReadOnlyList<string> Lines(string body, string data = "")
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void NestedOperatorsOnNumbers_GiveRapidsValues()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR num a := 7;
              VAR num b := 2;
              VAR dnum d := 3;
              TPWrite ValToStr(a + b * 3 - a / b);
              TPWrite ValToStr((a + 0.5) * (b - 4.25));
              TPWrite ValToStr(a DIV b + a MOD b * 10);
              TPWrite ValToStr(-a + d * 2);
              TPWrite ValToStr(17 DIV -5) + " " + ValToStr(-17 MOD 5);
              TPWrite ValToStr(a + b > 8) + " " + ValToStr(a - b <= 5) + " " + ValToStr(a * b = 14) + " " + ValToStr(a / b <> 3.5);
              TPWrite ValToStr(0 = -0) + " " + ValToStr(a < b OR b < a) + " " + ValToStr(a > b XOR b < a);
            """);

        Assert.Equal(["9.5", "-16.875", "13", "-1", "-3 -2", "TRUE TRUE TRUE FALSE", "TRUE TRUE FALSE"], lines);
    }

    [Fact]
    public void Conditions_OfIfWhileAndOr_StopAtTheLeftOperand_AsBefore()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR num n := 0;
              IF n > 0 AND Noisy(1) THEN
                TPWrite "no";
              ELSEIF n = 0 OR Noisy(2) THEN
                TPWrite "elseif";
              ENDIF
              IF n + 1 >= 1 AND Noisy(3) THEN
                TPWrite "and";
              ENDIF
              WHILE n * 2 < 6 AND NOT n = 10 DO
                n := n + 1.5;
              ENDWHILE
              TPWrite "n " \Num:=n;
              IF NOT (n < 3 OR n > 4) TPWrite "between";
            """,
            """
            FUNC bool Noisy(num k)
              TPWrite "noisy " \Num:=k;
              RETURN TRUE;
            ENDFUNC
            """);

        Assert.Equal(["elseif", "noisy 3", "and", "n 3", "between"], lines);
    }

    [Fact]
    public void ErrorsOfOperatorsInsideConditionsAndIndices_AreRapidsErrors()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR num zero := 0;
              VAR num half := 0.5;
              VAR num big := 1E300;
              VAR num list{3} := [10, 20, 30];
              IF 1 / zero > 0 TPWrite "no";
              IF 5 DIV half = 10 TPWrite "no";
              IF 5 MOD zero = 0 TPWrite "no";
              IF big * big > 0 TPWrite "no";
              TPWrite ValToStr(list{1 + half});
              TPWrite ValToStr(list{2 + 2});
              TPWrite ValToStr(list{half * 4 + 1});
            ERROR
              TPWrite "errno " + ValToStr(ERRNO = ERR_DIVZERO) + ValToStr(ERRNO = ERR_ARGVALERR) + ValToStr(ERRNO = ERR_NUMOVERFLOW) + ValToStr(ERRNO = ERR_OUTOFBND);
              TRYNEXT;
            """);

        Assert.Equal(
        [
            "errno TRUEFALSEFALSEFALSE", "errno FALSETRUEFALSEFALSE", "errno TRUEFALSEFALSEFALSE", "errno FALSEFALSETRUEFALSE",
            "errno FALSEFALSEFALSETRUE", "errno FALSEFALSEFALSETRUE", "30",
        ], lines);
    }

    [Fact]
    public void ForBoundsAndLocalArraySizes_FromExpressions()
    {
        IReadOnlyList<string> lines = Lines(
            """
              VAR num k := 2;
              FOR i FROM k * 2 TO k + 10 STEP k + 1.5 DO
                TPWrite "i " \Num:=i;
              ENDFOR
              Sized k + 1;
            """,
            """
            CONST num SIZE := 3;
            PROC Sized(num n)
              VAR num items{SIZE * 2 - 1};
              items{n * 2 - 1} := n;
              TPWrite ValToStr(items);
            ENDPROC
            """);

        Assert.Equal(["i 4", "i 7.5", "i 11", "[0,0,0,0,3]"], lines);
    }

    [Fact]
    public void AnOptionalParameterNotGiven_InANumberCondition_IsErrNotpres()
    {
        IReadOnlyList<string> lines = Lines(
            """
              Check \X:=4;
              Check;
            """,
            """
            PROC Check(\num X)
              IF X * 2 > 5 TPWrite "big";
              TPWrite "after";
            ERROR
              TPWrite "notpres " \Bool:=ERRNO = ERR_NOTPRES;
              TRYNEXT;
            ENDPROC
            """);

        Assert.Equal(["big", "after", "notpres TRUE", "after"], lines);
    }

    [Fact]
    public void SignalsAndStrings_InComparisons_TakeTheGeneralPath()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Signals = [("DO_1", "signaldo")] });
        twin.Load(("T.mod", """
            MODULE T
            VAR signaldo out1;
            PROC main()
              VAR string s := "ab";
              AliasIO "DO_1", out1;
              SetDO out1, 1;
              IF out1 = 1 AND s + "c" = "abc" TPWrite "both";
              IF out1 + 1 = 2 TPWrite "sum";
              TPWrite ValToStr(s <> "ab") + " " + ValToStr(out1 * 3);
            ENDPROC
            ENDMODULE
            """));

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["both", "sum", "FALSE 3"], twin.Pendant.Lines);
    }
}
