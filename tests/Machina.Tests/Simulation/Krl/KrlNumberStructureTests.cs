using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Structures of INT, REAL, BOOL and CHAR components held unboxed (issue 45, perf55k): what a program stores in a FRAME, E6POS,
/// E6AXIS or a STRUC of its own must read back as the same KRL value (an INT as an INT, a BOOL as a BOOL, a REAL bit for bit),
/// REAL into INT rounds as KRL assigns, copies are the holder's own, and conversions between position types keep S and T unset.
/// </summary>
public class KrlNumberStructureTests
{
    private static KrlTwinController Run(string source, string data)
    {
        var twin = new KrlTwinController();
        twin.Load([("prog.src", source), ("prog.dat", data)]);
        KrlProgramState state = twin.Run();
        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    private static object ValueOf(KrlTwinController twin, string name) => twin.Modules["prog"].Data[name].Value;

    [Fact]
    public void StrucOfSimpleComponents_ReadsBackEachKind_WithItsOwnTypeAndValue()
    {
        const string Data = """
            DEFDAT prog
              STRUC Mix INT n, REAL r, BOOL b, CHAR c, INT big
              DECL Mix m
              DECL INT n2 = 0
              DECL REAL r2 = 0.0
              DECL BOOL b2 = FALSE
              DECL CHAR c2
              DECL INT big2 = 0
              DECL REAL sum = 0.0
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL Mix local
              local.n = -7
              local.r = 0.1
              local.b = TRUE
              local.c = "q"
              local.big = 2000000000
              local.r = local.r + local.n
              local.n = 2.5
              m = local
              local.n = 99
              n2 = m.n
              r2 = m.r
              b2 = m.b
              c2 = m.c
              big2 = m.big
              sum = m.n + m.r
            END
            """;
        using KrlTwinController twin = Run(Source, Data);

        var m = (KrlStructValue)ValueOf(twin, "m");
        Assert.Equal(3, Assert.IsType<int>(m.Values[0])); // 2.5 into an INT rounds half away from zero; the copy kept it after local.n = 99
        Assert.Equal(BitConverter.DoubleToInt64Bits(0.1 + -7), BitConverter.DoubleToInt64Bits(Assert.IsType<double>(m.Values[1])));
        Assert.True(Assert.IsType<bool>(m.Values[2]));
        Assert.Equal('q', Assert.IsType<char>(m.Values[3]));
        Assert.Equal(2000000000, Assert.IsType<int>(m.Values[4]));
        Assert.Equal(3, Assert.IsType<int>(ValueOf(twin, "n2")));
        Assert.Equal(0.1 + -7, Assert.IsType<double>(ValueOf(twin, "r2")));
        Assert.True(Assert.IsType<bool>(ValueOf(twin, "b2")));
        Assert.Equal('q', Assert.IsType<char>(ValueOf(twin, "c2")));
        Assert.Equal(2000000000, Assert.IsType<int>(ValueOf(twin, "big2")));
        Assert.Equal(3 + (0.1 + -7), Assert.IsType<double>(ValueOf(twin, "sum")));
        Assert.Equal("{n 3, r -6.9, b TRUE, c q, big 2000000000}", KrlValues.Format(m));
    }

    [Fact]
    public void FrameComponents_FromAnArrayAndAnotherFrame_AreBitForBit_AndACopyIsItsOwn()
    {
        const string Data = """
            DEFDAT prog
              DECL REAL v[3]
              DECL FRAME kept
              DECL E6POS pos
              DECL FRAME before
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL FRAME f, g
              v[1] = 0.1
              v[2] = -0.0
              v[3] = 1.0 / 3.0
              f.X = v[1]
              f.Y = v[2]
              f.Z = v[3]
              f.A = 2
              g = f
              g.X = g.X * 3
              before = f
              f.B = f.X + f.Z
              kept = g
              pos = f
            END
            """;
        using KrlTwinController twin = Run(Source, Data);

        var kept = (KrlStructValue)ValueOf(twin, "kept");
        Assert.Equal(BitConverter.DoubleToInt64Bits(0.1 * 3), BitConverter.DoubleToInt64Bits((double)kept.Values[0]));
        Assert.Equal(BitConverter.DoubleToInt64Bits(-0.0), BitConverter.DoubleToInt64Bits((double)kept.Values[1]));
        Assert.Equal(BitConverter.DoubleToInt64Bits(1.0 / 3.0), BitConverter.DoubleToInt64Bits((double)kept.Values[2]));
        Assert.Equal(2.0, Assert.IsType<double>(kept.Values[3])); // an INT into a REAL component is a REAL
        Assert.Equal(0.0, (double)kept.Values[4]); // f.B was set after the copy
        var before = (KrlStructValue)ValueOf(twin, "before");
        Assert.Equal(0.1, (double)before.Values[0]);
        Assert.Equal(0.0, (double)before.Values[4]);
        var pos = (KrlStructValue)ValueOf(twin, "pos");
        Assert.Equal(0.1 + 1.0 / 3.0, (double)pos.Values[4]);
        Assert.Equal(0.1, (double)pos.Values[0]);
        Assert.False(pos.IsGiven(6)); // S and T of an E6POS made from a FRAME were never given
        Assert.False(pos.IsGiven(7));
        Assert.Equal(0, Assert.IsType<int>(pos.Values[6]));
    }

    [Fact]
    public void RealComponent_AsOutArgument_AndInConditions_ReadsAndWritesThrough()
    {
        const string Data = """
            DEFDAT prog
              DECL E6AXIS ax
              DECL INT hits = 0
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL E6AXIS a
              setv(a.A3, 12.5)
              setv(ax.A6, -4)
              IF a.A3 > 12.4 THEN
                hits = hits + 1
              ENDIF
              IF (ax.A6 == -4) AND (a.A1 == 0) THEN
                hits = hits + 10
              ENDIF
              ax.A1 = a.A3
            END

            DEF setv(x:OUT, value:IN)
              DECL REAL x, value
              x = value
            END
            """;
        using KrlTwinController twin = Run(Source, Data);

        var ax = (KrlStructValue)ValueOf(twin, "ax");
        Assert.Equal(12.5, Assert.IsType<double>(ax.Values[0]));
        Assert.Equal(-4.0, Assert.IsType<double>(ax.Values[5]));
        Assert.Equal(11, Assert.IsType<int>(ValueOf(twin, "hits")));
    }
}
