using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// REAL arrays held unboxed (issue 45, perf55a): what a program stores in a REAL array element (a REAL, an INT, a data list's
/// initial value, an OUT argument, EKI_GetReal's number) must read back as a REAL bit for bit, REAL into an INT array rounds as
/// KRL assigns, a copied array is its own, an index outside the array stops the program with the controller's message.
/// </summary>
public class KrlRealArrayTests
{
    private static double Element(KrlTwinController twin, string module, string name, int index)
    {
        object value = ((KrlArrayValue)twin.Modules[module].Data[name].Value)[index];
        return Assert.IsType<double>(value);
    }

    private static long Bits(double value) => BitConverter.DoubleToInt64Bits(value);

    [Fact]
    public void RealArrayElements_ReadBackBitForBit_ThroughEveryKindOfStore()
    {
        const string Data = """
            DEFDAT prog
              DECL REAL g[5]
              g[1] = 1.5
              g[2] = -0.0
              g[4] = 3
              DECL REAL grid[2,3]
              DECL INT gi[2]
              DECL REAL copyg[5]
              DECL REAL seen[9]
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL REAL loc[4]
              DECL REAL r
              DECL INT i
              loc[1] = 1.0 / 3.0
              loc[2] = 7
              i = 5
              loc[4] = i + 2
              grid[2,3] = loc[1] + g[1]
              gi[1] = loc[1] * 10
              gi[2] = g[1] + 1
              copyg = g
              copyg[2] = 9
              fill(loc[3])
              total(loc[], r)
              seen[1] = loc[1]
              seen[2] = loc[2]
              seen[3] = loc[3]
              seen[4] = r
              seen[5] = g[2]
              seen[6] = grid[2,3]
            END

            DEF fill(x:OUT)
              REAL x
              x = x + 100
            END

            DEF total(a[]:OUT, t:OUT)
              REAL a[]
              REAL t
              INT k
              t = 0
              FOR k = 1 TO 4
                t = t + a[k]
                a[k] = a[k] * 2
              ENDFOR
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load([("prog.src", Source), ("prog.dat", Data)]);
        KrlProgramState state = twin.Run();
        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");

        Assert.Equal(Bits(2.0 / 3.0), Bits(Element(twin, "prog", "seen", 0))); // 1/3 doubled by total's OUT array
        Assert.Equal(14.0, Element(twin, "prog", "seen", 1)); // INT 7 stored as a REAL, doubled
        Assert.Equal(200.0, Element(twin, "prog", "seen", 2)); // 0 + 100 through an OUT element, doubled
        Assert.Equal(Bits(1.0 / 3.0 + 7 + 100 + 7), Bits(Element(twin, "prog", "seen", 3)));
        Assert.Equal(Bits(-0.0), Bits(Element(twin, "prog", "seen", 4))); // the data list's -0.0 kept its sign
        Assert.Equal(Bits(1.0 / 3.0 + 1.5), Bits(Element(twin, "prog", "seen", 5)));
        Assert.Equal(3.0, Element(twin, "prog", "g", 3)); // the data list's INT 3 into a REAL element
        Assert.Equal(9.0, Element(twin, "prog", "copyg", 1));
        Assert.Equal(Bits(-0.0), Bits(Element(twin, "prog", "g", 1))); // the copy is its own
        var gi = (KrlArrayValue)twin.Modules["prog"].Data["gi"].Value;
        Assert.Equal(3, Assert.IsType<int>(gi[0])); // 3.33 rounds to 3
        Assert.Equal(3, Assert.IsType<int>(gi[1])); // 2.5 rounds away from 0
    }

    [Fact]
    public void RealArrayIndexOutside_StopsWithTheControllersMessage_AndKeepsTheElementsWritten()
    {
        using var twin = new KrlTwinController();
        twin.Load([("prog.src", "DEF prog( )\n  v[1] = 2.25\n  v[k] = 1\nEND\n"), ("prog.dat", "DEFDAT prog\n  DECL REAL v[3]\n  INT k = 4\nENDDAT\n")]);

        KrlProgramState state = twin.Run();

        Assert.Equal(KrlProgramState.Failed, state);
        Assert.Equal("Array index inadmissible: index 4 of v is outside 1 to 3 (prog.src, line 3)", twin.Error);
        Assert.Equal(2.25, Element(twin, "prog", "v", 0));
        Assert.Equal(0.0, Element(twin, "prog", "v", 2));
    }

    private const string Configuration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL><IP>127.0.0.1</IP><PORT>0</PORT><PROTOCOL>UDP</PROTOCOL><BUFFERING Mode="FIFO" Limit="64" /></INTERNAL>
          </CONFIGURATION>
          <RECEIVE>
            <XML>
              <ELEMENT Tag="Cmd/@V" Type="REAL" />
              <ELEMENT Tag="Cmd" Set_Flag="2" />
            </XML>
          </RECEIVE>
          <SEND>
            <XML>
              <ELEMENT Tag="State/@Left" />
            </XML>
          </SEND>
        </ETHERNETKRL>
        """;

    private const string Program = """
        DEF reals( )
          DECL EKI_STATUS ret
          DECL FRAME f
          ret = EKI_Init("Reals")
          ret = EKI_Open("Reals")
          WAIT FOR $FLAG[2]
          ret = EKI_GetReal("Reals", "Cmd/@V", slot_v[2, 3])
          ret = EKI_GetReal("Reals", "Cmd/@V", slot_v[1, 1])
          ret = EKI_GetReal("Reals", "Cmd/@V", x)
          ret = EKI_GetReal("Reals", "Cmd/@V", f.Y)
          fy = f.Y
          ret = EKI_GetReal("Reals", "Cmd/@V", slot_v[2, 1])
          ret = EKI_SetInt("Reals", "State/@Left", ret.Buff)
          ret = EKI_Send("Reals", "State")
          ret = EKI_Close("Reals")
        END
        """;

    [Fact]
    public async Task EkiGetReal_StoresTheNumberItRead_InARealElement_AVariable_AndAComponent()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Reals", Configuration);
        twin.Load(("reals.src", Program), ("reals.dat", "DEFDAT reals\n  DECL REAL slot_v[2,3]\n  REAL x = 0.0\n  REAL fy = 0.0\nENDDAT\n"));
        string document = "<Cmd V=\"-0\"/><Cmd V=\"0.1\"/><Cmd V=\"1e3\"/><Cmd V=\"7\"/><Cmd V=\"-1234.567890123\"/>";

        (KrlProgramState state, string answer) = await EkiUdpExchange.RunAsync(twin, "Reals", document);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("<State Left=\"0\" />", answer);
        Assert.Equal(Bits(-0.0), Bits(Element(twin, "reals", "slot_v", 5)));
        Assert.Equal(Bits(0.1), Bits(Element(twin, "reals", "slot_v", 0)));
        Assert.Equal(1000.0, Assert.IsType<double>(twin.Modules["reals"].Data["x"].Value));
        Assert.Equal(7.0, Assert.IsType<double>(twin.Modules["reals"].Data["fy"].Value));
        Assert.Equal(Bits(-1234.567890123), Bits(Element(twin, "reals", "slot_v", 3)));
        Assert.Equal(0.0, Element(twin, "reals", "slot_v", 1));
    }
}
