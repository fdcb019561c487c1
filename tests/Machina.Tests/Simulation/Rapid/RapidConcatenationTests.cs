using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A chain of string <c>+</c> makes one string (issue 45: our driver's acknowledgement, <c>"@" + NumToStr(id, 0) + " " + NumToStr(code, 0) + ";"</c>,
/// made four strings, three of them thrown away at once). The value, the order in which the operands are evaluated, their errors and
/// the 80-character limit of a stored string stay what the operators gave one at a time.
/// </summary>
public class RapidConcatenationTests
{
    private static RapidTwinController Load(string body, string data = "")
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        return twin;
    }

    private static IReadOnlyList<string> Run(string body, string data = "")
    {
        RapidTwinController twin = Load(body, data);
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void Chains_GiveTheStringOfTheirOperators_HoweverNested()
    {
        IReadOnlyList<string> lines = Run(
            """
              VAR string s := "b";
              VAR num id := 12;
              TPWrite "@" + NumToStr(id, 0) + " " + NumToStr(id + 1, 0) + ";";
              TPWrite "a" + (s + ("c" + s)) + "d";
              TPWrite ("x" + s) + ("y" + (s + "z"));
              TPWrite "" + "" + s + "";
              TPWrite s + s;
              s := s + s + s;
              TPWrite s + StrPart(s + "12345", 3, 3);
            """);

        Assert.Equal(["@12 13;", "abcbd", "xbybz", "b", "bb", "bbbb12"], lines);
    }

    [Fact]
    public void Operands_AreEvaluatedLeftToRight_AndTheFirstErrorStops()
    {
        IReadOnlyList<string> lines = Run(
            """
              TPWrite Said("1") + (Said("2") + Said("3")) + Said("4");
              Optional;
              Optional \Text:="given";
            """,
            """
            FUNC string Said(string text)
              TPWrite "evaluated " + text;
              RETURN text;
            ENDFUNC
            PROC Optional(\string Text)
              TPWrite Said("before") + Text + Said("after");
            ERROR
              IF ERRNO = ERR_NOTPRES THEN
                TPWrite "not present";
                RETURN;
              ENDIF
            ENDPROC
            """);

        Assert.Equal(
            ["evaluated 1", "evaluated 2", "evaluated 3", "evaluated 4", "1234", "evaluated before", "not present",
             "evaluated before", "evaluated after", "beforegivenafter"],
            lines);
    }

    [Fact]
    public void AStoredChainLongerThan80Characters_IsStillTooLong_ButAPassingOneIsNot()
    {
        const string Forty = "0123456789012345678901234567890123456789";
        IReadOnlyList<string> fits = Run($"""
              VAR string s;
              s := StrPart("{Forty}" + "{Forty}" + "x", 79, 3);
              TPWrite s;
              s := "{Forty}" + "{Forty}";
              TPWrite NumToStr(StrLen(s), 0);
            """);
        Assert.Equal(["89x", "80"], fits);

        RapidTwinController tooLong = Load($"""
              VAR string s;
              s := "{Forty}" + "{Forty}" + "x";
            """);
        Assert.Equal(RapidProgramState.Failed, tooLong.Run());
        Assert.Contains("longer than 80", tooLong.Error, StringComparison.Ordinal);
    }

    [Fact]
    public void AChainOfFiveStrings_MakesOneString()
    {
        const int Calls = 400;
        RapidTwinController twin = Load(
            $"""
              Ack;
              FOR i FROM 1 TO {Calls} DO
                Ack;
              ENDFOR
            """,
            """
            VAR string message;
            VAR string one := "1";
            VAR string two := "2";
            PROC Ack()
              message := "@" + one + " " + two + ";";
            ENDPROC
            """);
        long before = GC.GetAllocatedBytesForCurrentThread();
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        long perCall = (GC.GetAllocatedBytesForCurrentThread() - before) / Calls;

        // "@1 2;" is a string of 36 bytes; one per operator (four, 26-36 B each, ~124 B) before.
        Assert.InRange(perCall, 0, 80);
    }
}
