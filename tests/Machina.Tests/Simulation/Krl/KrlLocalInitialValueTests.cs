using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// A routine's structure and array locals are made at their first use (the interpreter does not build them at every call): read
/// before any assignment they have their initial values, a component or element written first keeps the others at theirs, an
/// OUT argument writes into them, and every call starts from the initial values again.
/// </summary>
public class KrlLocalInitialValueTests
{
    private const string Data = "DEFDAT locals\n  DECL REAL seen[8]\n  DECL INT calls = 0\nENDDAT\n";

    [Fact]
    public void StructureAndArrayLocals_ReadWrittenAndPassedBeforeAnyAssignment_InitialValuesEveryCall()
    {
        const string Source = """
            DEF locals( )
              probe( )
              probe( )
            END

            DEF probe( )
              DECL FRAME f, g
              DECL E6POS p
              DECL INT counts[3]
              DECL REAL r
              calls = calls + 1
              seen[calls] = f.X + f.C + counts[2]
              g.Y = 5 + calls
              seen[calls + 2] = g.X + g.Y
              counts[3] = counts[3] + 7
              seen[calls + 4] = counts[1] + counts[3]
              fill(p)
              seen[calls + 6] = p.Z + p.X
              f.X = 100
              counts[2] = 100
            END

            DEF fill(q:OUT)
              DECL E6POS q
              q.Z = q.Z + 3
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("locals.src", Source), ("locals.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        object[] seen = ((KrlArrayValue)twin.Modules["locals"].Data["seen"].Value).ToObjects();
        // Each call: f and counts unread (0, even after the first call set f.X and counts[2]), g.Y set (6, then 7) with g.X 0,
        // counts[3] 0 + 7 each call, p's Z 0 + 3 through the OUT parameter.
        Assert.Equal([0.0, 0.0, 6.0, 7.0, 7.0, 7.0, 3.0, 3.0], seen.Select(v => (double)v));
    }
}
