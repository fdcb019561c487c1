using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Guards for session 34's KRL interpreter changes (perf54k): INT, REAL and BOOL operations evaluated without boxes, expressions
/// switched on their kind, stores of data list variables without a place, and the declared interrupts kept in priority order.
/// Each keeps what the interpreter did: the values and errors here are those of the build before.
/// </summary>
public class KrlTypedEvaluationTests
{
    private static KrlTwinController Run(string source, string data, KrlProgramState expected = KrlProgramState.Finished)
    {
        var twin = new KrlTwinController(new KrlTwinOptions { Limits = TwinLimits.Default });
        twin.Load(("prog.src", source), ("prog.dat", data));
        Assert.Equal(expected, twin.Run());
        return twin;
    }

    private static object Data(KrlTwinController twin, string name) => twin.Modules["prog"].Data[name].Value;

    [Fact]
    public void IntAndRealOperations_FollowKrl_IntDivisionTruncates_AndAnIntMeetsARealAsAReal()
    {
        using KrlTwinController twin = Run(
            "DEF prog( )\n  DECL INT i\n  DECL REAL r\n  i = 7\n  r = 0.5\n  a = i / 2\n  b = -i / 2\n  c = i / 2.0\n  d = (i / 2) * r + i * 2 - 1\n"
            + "  e = i B_AND 6\n  f = (i B_OR 8) B_EXOR 1\n  g = i * r + r / 4\n  h = i - 10\n  k = r * 3 - i\nEND\n",
            "DEFDAT prog\n  INT a = 0\n  INT b = 0\n  REAL c = 0.0\n  REAL d = 0.0\n  INT e = 0\n  INT f = 0\n  REAL g = 0.0\n  INT h = 0\n  REAL k = 0.0\nENDDAT\n");

        Assert.Equal(3, (int)Data(twin, "a"));
        Assert.Equal(-3, (int)Data(twin, "b"));
        Assert.Equal(3.5, (double)Data(twin, "c"));
        Assert.Equal(14.5, (double)Data(twin, "d"));
        Assert.Equal(6, (int)Data(twin, "e"));
        Assert.Equal(14, (int)Data(twin, "f"));
        Assert.Equal(3.625, (double)Data(twin, "g"));
        Assert.Equal(-3, (int)Data(twin, "h"));
        Assert.Equal(-5.5, (double)Data(twin, "k"));
    }

    [Fact]
    public void Conditions_CompareIntsRealsBoolsAndChars_AndEvaluateBothOperandsOfAndOr()
    {
        using KrlTwinController twin = Run(
            "DEF prog( )\n  DECL INT i\n  DECL CHAR x, y\n  i = 3\n  x = \"A\"\n  y = \"B\"\n"
            + "  IF i == 3.0 THEN\n    n = n + 1\n  ENDIF\n  IF i < 3.5 THEN\n    n = n + 10\n  ENDIF\n  IF x < y THEN\n    n = n + 100\n  ENDIF\n"
            + "  IF (i > 2) == TRUE THEN\n    n = n + 1000\n  ENDIF\n  IF (i <> 3) OR (2.5 >= i) THEN\n    n = -1\n  ENDIF\n"
            + "  IF (i >= 4) AND side() THEN\n    n = -2\n  ENDIF\n  IF (i <= 3) OR side() THEN\n    n = n + 10000\n  ENDIF\n"
            + "  p = (1 < 2) EXOR (2 < 1)\n  q = NOT (i == 3)\n  WHILE i > 0\n    i = i - 1\n  ENDWHILE\n  s = i\nEND\n"
            + "DEFFCT BOOL side( )\n  calls = calls + 1\n  RETURN TRUE\nENDFCT\n",
            "DEFDAT prog\n  INT n = 0\n  INT calls = 0\n  BOOL p = FALSE\n  BOOL q = TRUE\n  INT s = 9\nENDDAT\n");

        Assert.Equal(11111, (int)Data(twin, "n"));
        Assert.Equal(2, (int)Data(twin, "calls")); // both AND and OR evaluated their right operand
        Assert.True((bool)Data(twin, "p"));
        Assert.False((bool)Data(twin, "q"));
        Assert.Equal(0, (int)Data(twin, "s"));
    }

    [Theory]
    [InlineData("i = i / z")]
    [InlineData("r = r / z")]
    [InlineData("r = r / (z * 1.0)")]
    [InlineData("IF 1 / z > 0 THEN\n    i = 1\n  ENDIF")]
    public void ADivisionByZero_StopsTheProgram(string statement)
    {
        using KrlTwinController twin = Run(
            "DEF prog( )\n  DECL INT i, z\n  DECL REAL r\n  i = 1\n  r = 1\n  z = 0\n  " + statement + "\nEND\n", "DEFDAT prog\nENDDAT\n",
            KrlProgramState.Failed);

        Assert.Contains("Division by 0", twin.Error);
    }

    [Fact]
    public void AnArrayIndex_FromAnIntOperation_IsCheckedAgainstTheArray()
    {
        using KrlTwinController twin = Run(
            "DEF prog( )\n  DECL INT k\n  k = 2\n  v[k * 2 - 1] = 7.5\n  w = v[k + 1] + v[1]\n  v[k * 3 - 2] = 1\nEND\n",
            "DEFDAT prog\n  REAL v[3]\n  REAL w = 0.0\nENDDAT\n", KrlProgramState.Failed);

        Assert.Equal(7.5, (double)Data(twin, "w"));
        Assert.Contains("Array index inadmissible: index 4 of v is outside 1 to 3", twin.Error);
    }

    [Fact]
    public void AnInterruptDeclaredAgain_ReplacesTheOldAtItsPriority_AndTheHighestPriorityRunsFirst()
    {
        using KrlTwinController twin = Run(
            "DEF prog( )\n  INTERRUPT DECL 5 WHEN go1 DO h(1)\n  INTERRUPT ON 5\n  INTERRUPT DECL 5 WHEN go2 DO h(2)\n  INTERRUPT ON 5\n"
            + "  INTERRUPT DECL 7 WHEN go2 DO h(7)\n  INTERRUPT ON 7\n  INTERRUPT DECL 3 WHEN go2 DO h(3)\n  INTERRUPT ON 3\n"
            + "  go1 = TRUE\n  WAIT SEC 0\n  go2 = TRUE\n  WAIT SEC 0\n  INTERRUPT OFF 3\n  go2 = FALSE\n  WAIT SEC 0\n  go2 = TRUE\n  WAIT SEC 0\nEND\n"
            + "DEF h(n:IN)\n  DECL INT n\n  seen = seen * 10 + n\nEND\n",
            "DEFDAT prog\n  BOOL go1 = FALSE\n  BOOL go2 = FALSE\n  INT seen = 0\nENDDAT\n");

        // Priorities 3, 5 (its second declaration: h(2)) and 7 on go2's first edge; 5 and 7 on its second (3 switched off); never h(1).
        Assert.Equal(32727, (int)Data(twin, "seen"));
    }
}
