using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// TEST runs the statements of the first CASE whose value equals the tested value, else DEFAULT (RAPID Overview, "TEST"). A TEST
/// whose CASE values are all number literals finds its CASE by a look-up; it must choose what comparing the values in order chooses.
/// </summary>
public class RapidTestStatementTests
{
    private static List<string> Run(string body)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\nVAR num calls := 0;\nFUNC num Counted(num v)\n  calls := calls + 1;\n  RETURN v;\nENDFUNC\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.Equal(RapidProgramState.Finished, twin.Run());
        return [.. twin.Pendant.Lines];
    }

    private const string NumberCases = """
          FOR i FROM -2 TO 7 DO
            TEST i / 2
            CASE 0:
              TPWrite "zero";
            CASE 1, 2:
              TPWrite "one or two" \Num:=i;
            CASE 1:
              TPWrite "never: the first CASE of 1 wins";
            CASE 1.5, 3.5:
              TPWrite "one and a half or three and a half" \Num:=i;
            DEFAULT:
              TPWrite "default" \Num:=i;
            ENDTEST
          ENDFOR
          TEST -0
          CASE 0:
            TPWrite "minus zero is zero";
          ENDTEST
          TEST 5
          CASE 1, 2:
            TPWrite "never";
          ENDTEST
          TPWrite "no CASE, no DEFAULT: on";
        """;

    [Fact]
    public void NumberLiteralCases_FirstMatchingCaseElseDefault_MinusZeroIsZero()
    {
        Assert.Equal(
        [
            "default-2", "default-1", "zero", "default1", "one or two2", "one and a half or three and a half3",
            "one or two4", "default5", "default6", "one and a half or three and a half7", "minus zero is zero", "no CASE, no DEFAULT: on",
        ], Run(NumberCases));
    }

    [Fact]
    public void CasesThatAreNotAllLiterals_AreComparedInOrder_UntilTheFirstMatch()
    {
        List<string> lines = Run("""
              TEST 2
              CASE Counted(1), Counted(2), Counted(3):
                TPWrite "matched after" \Num:=calls;
              CASE 2:
                TPWrite "never";
              ENDTEST
              TEST "b"
              CASE "a":
                TPWrite "never";
              CASE "b":
                TPWrite "string b";
              ENDTEST
            """);

        Assert.Equal(["matched after2", "string b"], lines);
    }
}
