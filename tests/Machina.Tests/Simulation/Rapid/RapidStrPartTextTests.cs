using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// StrToVal reads a StrPart argument in place (issue 45: our driver converts every number of a request with
/// <c>StrToVal(StrPart(chunk, position, length), values{n})</c>, and each StrPart made a string thrown away at once). The values, the
/// whitespace StrToVal ignores, StrPart's errors and the order of evaluation stay what StrPart's string gave.
/// </summary>
public class RapidStrPartTextTests
{
    private static RapidTwinController Load(string body, string data = "")
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        return twin;
    }

    [Fact]
    public void StrToValOfAPart_IsStrToValOfThePartsString()
    {
        RapidTwinController twin = Load(
            """
              VAR num value := 7;
              VAR bool flag;
              VAR bool ok;
              ok := StrToVal(StrPart("@12 1121.5 -0.25;", 5, 6), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal(StrPart("x -0.25 y", 2, 7), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal(StrPart("a2.5E2b", 2, 5), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal(StrPart("1-2", 1, 2), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal(StrPart("abc", 2, 0), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal(StrPart("xTRUEx", 2, 4), flag);
              TPWrite ValToStr(ok) + " " + ValToStr(flag);
              ok := StrToVal(StrPart("9", 1, 1), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value) + " " + StrPart("@12 1121.5;", 5, 6);
            """);
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["TRUE 1121.5", "TRUE -0.25", "TRUE 250", "FALSE 250", "FALSE 250", "TRUE TRUE", "TRUE 9 1121.5"], twin.Pendant.Lines);
    }

    [Fact]
    public void APartOutsideTheString_IsStrPartsError_BeforeStrToValWrites()
    {
        RapidTwinController twin = Load(
            """
              VAR num value := 7;
              VAR bool ok;
              ok := StrToVal(StrPart("12345", 4, 3), value);
              TPWrite "not reached";
            ERROR
              TPWrite "errno " + ValToStr(ERRNO = ERR_ARGVALERR) + " " + ValToStr(value);
            """);
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["errno TRUE 7"], twin.Pendant.Lines);

        RapidTwinController unhandled = Load("VAR num value;\nVAR bool ok;\nok := StrToVal(StrPart(\"12345\", 0, 2), value);");
        Assert.Equal(RapidProgramState.Failed, unhandled.Run());
        Assert.Contains("StrPart: characters 0 to 1 are outside the string of length 5", unhandled.Error, StringComparison.Ordinal);
    }

    [Fact]
    public void StrPartsArguments_AreEvaluatedOnce_InOrder()
    {
        RapidTwinController twin = Load(
            """
              VAR num value;
              VAR bool ok;
              ok := StrToVal(StrPart(Said("ab42cd"), Pos(3), Len(2)), value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
            """,
            """
            FUNC string Said(string s)
              TPWrite "str";
              RETURN s;
            ENDFUNC
            FUNC num Pos(num p)
              TPWrite "pos";
              RETURN p;
            ENDFUNC
            FUNC num Len(num n)
              TPWrite "len";
              RETURN n;
            ENDFUNC
            """);
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["str", "pos", "len", "TRUE 42"], twin.Pendant.Lines);
    }

    [Fact]
    public void StrToValOfAPart_MakesNoStringForThePart()
    {
        const int Calls = 2000;
        RapidTwinController twin = Load(
            $"""
              FOR i FROM 1 TO {Calls} DO
                ok := StrToVal(StrPart(chunk, 5, 12), value);
              ENDFOR
            """,
            """
            VAR string chunk := "@12 751.000000125 0 1121.5;";
            VAR num value;
            VAR bool ok;
            """);
        long before = GC.GetAllocatedBytesForCurrentThread();
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        long perCall = (GC.GetAllocatedBytesForCurrentThread() - before) / Calls;

        // The number's box (24 B) is all a conversion keeps; the part "751.00000012" (46 B) was made and dropped at each call before.
        Assert.InRange(perCall, 0, 40);
    }
}
