using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EthernetKRL reads by tag (issue 45, perf51k): a channel finds a tag's memory by the string's reference when the program named
/// it before, so a tag written as a literal and the same tag made at run time from a CHAR array (a new string at every call, more
/// of them than the channel keeps) must take from the one memory, in order; and EKI_GetInt reads integer text as it is and any
/// other number through a REAL, rounded.
/// </summary>
public class EkiNamedTagTests
{
    private const string Configuration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL><IP>127.0.0.1</IP><PORT>0</PORT><PROTOCOL>UDP</PROTOCOL><BUFFERING Mode="FIFO" Limit="64" /></INTERNAL>
          </CONFIGURATION>
          <RECEIVE>
            <XML>
              <ELEMENT Tag="Cmd/V/@N" Type="INT" />
              <ELEMENT Tag="Cmd/W/@K" Type="INT" />
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
        DEF named( )
          DECL EKI_STATUS ret
          DECL CHAR tag[8]
          DECL INT i
          ret = EKI_Init("Named")
          ret = EKI_Open("Named")
          WAIT FOR $FLAG[2]
          tag[] = "Cmd/V/@N"
          FOR i = 1 TO 20
            ret = EKI_GetInt("Named", "Cmd/V/@N", vals[2 * i - 1])
            ret = EKI_GetInt("Named", tag[], vals[2 * i])
          ENDFOR
          FOR i = 1 TO 7
            ret = EKI_GetInt("Named", "Cmd/W/@K", ks[i])
          ENDFOR
          ret = EKI_SetInt("Named", "State/@Left", ret.Buff)
          ret = EKI_Send("Named", "State")
          ret = EKI_Close("Named")
        END
        """;

    [Fact]
    public async Task TagsAsLiteralsAndMadeAtRunTime_TakeFromOneMemoryInOrder_AndIntegerTextIsReadAsIt()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Named", Configuration);
        twin.Load(("named.src", Program), ("named.dat", "DEFDAT named\n  DECL INT vals[40]\n  DECL INT ks[7]\nENDDAT\n"));
        string values = string.Concat(Enumerable.Range(1, 40).Select(n => $"<V N=\"{n}\"/>"));
        string numbers = string.Concat(new[] { "12", "-3", "2.5", "1e2", "+4", "007", "-0" }.Select(k => $"<W K=\"{k}\"/>"));

        (KrlProgramState state, string answer) = await EkiUdpExchange.RunAsync(twin, "Named", $"<Cmd>{values}{numbers}</Cmd>");

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("<State Left=\"0\" />", answer);
        object[] read = ((KrlArrayValue)twin.Modules["named"].Data["vals"].Value).ToObjects();
        Assert.Equal(Enumerable.Range(1, 40), read.Select(v => (int)v));
        object[] ks = ((KrlArrayValue)twin.Modules["named"].Data["ks"].Value).ToObjects();
        Assert.Equal([12, -3, 2, 100, 4, 7, 0], ks.Select(v => (int)v));
    }
}
