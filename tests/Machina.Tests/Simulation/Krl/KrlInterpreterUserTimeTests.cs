using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Guards for session 33's KRL interpreter changes (perf53k): a routine's locals taken once per routine, the step budget counted
/// inline, numbers read with the usual case inlined, $TIMER read through its cell. Each keeps what the interpreter did: the
/// values and errors here are those of the build before.
/// </summary>
public class KrlInterpreterUserTimeTests
{
    private static KrlTwinController Ran(string source, string data, TwinLimits? limits = null)
    {
        var twin = new KrlTwinController(new KrlTwinOptions { Limits = limits ?? TwinLimits.Default });
        twin.Load(("prog.src", source), ("prog.dat", data));
        Assert.Equal(KrlProgramState.Finished, twin.Run());
        return twin;
    }

    [Fact]
    public void ARoutinesLocalArrays_AreGivenBackAtEachReturn_AndItsLocalsStartEmptyAtEachCall()
    {
        // 900,000 elements a call, twenty calls: the twin's total (4,000,000) holds only if each return gives them back.
        using KrlTwinController twin = Ran(
            "DEF prog( )\n  DECL INT k\n  FOR k = 1 TO 20\n    r(k)\n  ENDFOR\nEND\n"
            + "DEF r(k:IN)\n  DECL INT k, n\n  DECL INT a[900000]\n  DECL REAL x\n  total = total + a[k] + n\n  a[k] = k\n  n = k\n  x = x + k\n  sum = sum + x\nEND\n",
            "DEFDAT prog\n  INT total = 0\n  REAL sum = 0.0\nENDDAT\n");

        Assert.Equal(0, (int)twin.Modules["prog"].Data["total"].Value);
        Assert.Equal(210.0, (double)twin.Modules["prog"].Data["sum"].Value);
    }

    [Fact]
    public void NumbersConvert_AsKrlAssigns_HalfAwayFromZero()
    {
        using KrlTwinController twin = Ran(
            "DEF prog( )\n  DECL REAL r\n  r = 2.5\n  i1 = r\n  r = -2.5\n  i2 = r\n  r = 7\n  i3 = r * 2\n  a[1] = 1.5\n  a[3] = 4\n  x = a[i1] + a[1]\nEND\n",
            "DEFDAT prog\n  INT i1 = 0\n  INT i2 = 0\n  REAL i3 = 0.0\n  INT a[3]\n  REAL x = 0.0\nENDDAT\n");

        Assert.Equal(3, (int)twin.Modules["prog"].Data["i1"].Value);
        Assert.Equal(-3, (int)twin.Modules["prog"].Data["i2"].Value);
        Assert.Equal(14.0, (double)twin.Modules["prog"].Data["i3"].Value);
        Assert.Equal(6.0, (double)twin.Modules["prog"].Data["x"].Value); // a[3] = 4 (i1 is 3), a[1] = 2 (1.5 rounded)
    }

    [Fact]
    public void TheStepBudget_StillStopsAnEndlessLoop_WithItsMessage()
    {
        using var twin = new KrlTwinController(new KrlTwinOptions { Limits = TwinLimits.Default with { MaxSteps = 1000 } });
        twin.Load(("prog.src", "DEF prog( )\n  DECL INT i\n  LOOP\n    i = i + 1\n  ENDLOOP\nEND\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.StartsWith("the program ran more than 1,000 statements and loop turns (the verification's step budget): an endless loop?", twin.Error);
    }

    [Fact]
    public void ATimerRead_CountsTheProgramTime_ThroughItsCell()
    {
        using KrlTwinController twin = Ran(
            "DEF prog( )\n  $TIMER[3] = 0\n  $TIMER_STOP[3] = FALSE\n  WAIT SEC 0.25\n  t = $TIMER[3]\n  $TIMER_STOP[3] = TRUE\n  WAIT SEC 0.25\n  u = $TIMER[3]\nEND\n",
            "DEFDAT prog\n  INT t = 0\n  INT u = 0\nENDDAT\n");

        Assert.Equal(250, (int)twin.Modules["prog"].Data["t"].Value);
        Assert.Equal(250, (int)twin.Modules["prog"].Data["u"].Value);
    }
}
