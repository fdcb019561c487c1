using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The interpreter reuses argument arrays and OUT places from call to call: a call nested in another's arguments and a recursion
/// each write the variables their own arguments name (a reused place of the wrong call would write another).
/// </summary>
public class KrlCallArgumentsTests
{
    private const string Data = "DEFDAT args\n  DECL INT a = 1, b = 2, c = 3, sum = 0, r = 0, depths[12]\nENDDAT\n";

    [Fact]
    public void NestedAndRecursiveCallsWithOutArguments_EachWritesItsOwnVariables()
    {
        const string Source = """
            DEF args( )
              twice(a, plus(c, bump(b)))
              r = down(11, sum)
            END

            DEFFCT INT bump(v:OUT)
              DECL INT v
              v = v + 10
              RETURN v
            ENDFCT

            DEFFCT INT plus(x:OUT, y:IN)
              DECL INT x, y
              x = x + y
              RETURN x
            ENDFCT

            DEF twice(x:OUT, y:IN)
              DECL INT x, y
              x = x + 2 * y
            END

            DEFFCT INT down(n:IN, acc:OUT)
              DECL INT n, acc, inner
              depths[n + 1] = n
              IF n == 0 THEN
                RETURN 0
              ENDIF
              acc = acc + n
              inner = down(n - 1, acc)
              RETURN inner + 1
            ENDFCT
            """;
        using var twin = new KrlTwinController();
        twin.Load(("args.src", Source), ("args.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        var data = twin.Modules["args"].Data;
        // bump(b): b = 12, returns 12; plus(c, 12): c = 3 + 12 = 15, returns 15; twice(a, 15): a = 1 + 30 = 31.
        Assert.Equal(12, (int)data["b"].Value);
        Assert.Equal(15, (int)data["c"].Value);
        Assert.Equal(31, (int)data["a"].Value);
        // down(11, sum): sum = 11 + 10 + ... + 1 = 66 through eleven nested OUT arguments; 11 levels below the first.
        Assert.Equal(66, (int)data["sum"].Value);
        Assert.Equal(11, (int)data["r"].Value);
        Assert.Equal(Enumerable.Range(0, 12), ((KrlArrayValue)data["depths"].Value).ToObjects().Select(v => (int)v));
    }
}
