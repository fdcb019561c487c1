using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The interpreter writes a component of a local structure, and finds an element or row of an array for an OUT argument, without
/// making the variable's place first; structures of simple components are copied as arrays; a motion reads $BASE, $TOOL and $VEL
/// through cells found once. Each must write what and where the longer way did, and fail as it did.
/// </summary>
public class KrlDirectWriteTests
{
    private const string Data = """
        DEFDAT direct
          DECL INT glob[4], outx = 0
          DECL REAL grid[2,3], rx = 0, ry = 0, rs = 0, copyx = 0
          DECL CHAR rows[2,5], word[5]
          DECL FRAME kept
        ENDDAT

        """;

    /// <summary>Two routines that write their OUT argument: one INT, one REAL.</summary>
    private const string Setters = """

        DEF seti(x:OUT, v:IN)
          DECL INT x, v
          x = v
        END

        DEF setr(x:OUT, v:IN)
          DECL REAL x, v
          x = v
        END
        """;

    [Fact]
    public void ComponentsOfLocals_ElementsAndRowsAsOutArguments_WriteTheirOwnPlaces()
    {
        const string Source = """
            DEF direct( )
              DECL INT loc[3]
              DECL REAL lgrid[2,2]
              DECL FRAME f
              DECL E6POS p
              f = {X 1.0, Y 2.0, Z 3.0, A 0.0, B 0.0, C 0.0}
              f.X = 10
              f.Y = f.X + 0.5
              kept = f
              f.X = 99
              copyx = kept.X
              p = {X 0.0, Y 0.0, Z 0.0, A 0.0, B 0.0, C 0.0}
              p.S = 6
              rs = p.S
              rx = f.X
              ry = f.Y
              seti(loc[2], 5)
              seti(glob[3], 7)
              setr(grid[2, 3], 1.5)
              setr(lgrid[2, 1], 2.5)
              grid[1, 1] = lgrid[2, 1]
              outx = loc[2] + glob[3]
              settext(rows[2, ], "AB")
              word[] = "WXYZ"
              word[] = "Q"
            END

            DEF settext(t[]:OUT, s[]:IN)
              DECL CHAR t[], s[]
              t[1] = s[1]
              t[2] = s[2]
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("direct.src", Source + Setters), ("direct.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        var data = twin.Modules["direct"].Data;
        Assert.Equal(99.0, (double)data["rx"].Value);
        Assert.Equal(10.5, (double)data["ry"].Value);
        Assert.Equal(6.0, (double)data["rs"].Value);
        // kept took a copy: the later f.X = 99 is not in it.
        Assert.Equal(10.0, (double)data["copyx"].Value);
        Assert.Equal(10.0, ((KrlStructValue)data["kept"].Value).Number("X"));
        Assert.Equal(12, (int)data["outx"].Value);
        Assert.Equal([0, 0, 7, 0], ((KrlArrayValue)data["glob"].Value).ToObjects().Select(v => (int)v));
        Assert.Equal([2.5, 0, 0, 0, 0, 1.5], ((KrlArrayValue)data["grid"].Value).ToObjects().Select(v => (double)v));
        Assert.Equal("\0\0\0\0\0AB\0\0\0", string.Concat(((KrlArrayValue)data["rows"].Value).ToObjects().Select(v => (char)v)));
        Assert.Equal("Q\0\0\0\0", string.Concat(((KrlArrayValue)data["word"].Value).ToObjects().Select(v => (char)v)));
    }

    [Theory]
    [InlineData("seti(loc[4], 1)", "Array index inadmissible: index 4 of loc is outside 1 to 3")]
    [InlineData("seti(glob[0], 1)", "Array index inadmissible: index 0 of glob is outside 1 to 4")]
    [InlineData("setr(grid[3, 1], 1.0)", "Array index inadmissible: index 3 of grid is outside 1 to 2")]
    public void OutArgumentOutsideItsArray_StopsWithTheControllersMessage(string call, string message)
    {
        string source = $"""
            DEF direct( )
              DECL INT loc[3]
              {call}
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("direct.src", source + Setters), ("direct.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.Equal(KrlProgramState.Failed, state);
        Assert.Contains(message, twin.Error);
    }

    [Fact]
    public void BaseChangedBetweenMotions_TheSameTargetMovesWithIt()
    {
        const string Source = """
            DEF direct( )
              DECL FRAME t
              PTP $AXIS_ACT
              t = $POS_ACT
              t.X = t.X - 20
              LIN t
              $BASE = {X 0.0, Y 15.0, Z -10.0, A 0.0, B 0.0, C 0.0}
              LIN t
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("direct.src", Source), ("direct.dat", Data));
        var start = twin.Arm.Tcp;

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        var end = twin.Arm.Tcp.Position;
        Assert.Equal(start.Position.X - 20, end.X, 6);
        Assert.Equal(start.Position.Y + 15, end.Y, 6);
        Assert.Equal(start.Position.Z - 10, end.Z, 6);
    }
}
