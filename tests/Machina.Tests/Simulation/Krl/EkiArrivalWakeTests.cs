using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EthernetKRL hands the documents of one arrival to the program together (issue 45, perf52w): their values are stored, then
/// their flags are set once, so a program waiting for the flag wakes once per arrival and finds every document, instead of once
/// per document while the reader still stores the others. Counted by the twin's inputs version (every flag set moves it, and a
/// program in WAIT FOR wakes at each move), not by time.
/// </summary>
public class EkiArrivalWakeTests
{
    private const string Channel = "Wakes";

    private const string Configuration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL><ALIVE Set_Flag="1"/><IP>127.0.0.1</IP><PORT>0</PORT><PROTOCOL>TCP</PROTOCOL><BUFFERING Mode="FIFO" Limit="64"/></INTERNAL>
          </CONFIGURATION>
          <RECEIVE>
            <XML>
              <ELEMENT Tag="DT/A/@N" Type="INT"/>
              <ELEMENT Tag="DT" Set_Flag="2"/>
              <ELEMENT Tag="B" Set_Flag="3"/>
            </XML>
          </RECEIVE>
          <SEND><XML><ELEMENT Tag="S/@N"/></XML></SEND>
        </ETHERNETKRL>
        """;

    private const string OpenProgram = """
        DEF wakes_open( )
          DECL EKI_STATUS ret
          ret = EKI_Init("Wakes")
          ret = EKI_Open("Wakes")
        END
        """;

    private const string TakeProgram = """
        DEF wakes_take( )
          DECL EKI_STATUS ret
          DECL INT i
          ret = EKI_CheckBuffer("Wakes", "DT/A/@N")
          got = ret.Buff
          FOR i = 1 TO got
            ret = EKI_GetInt("Wakes", "DT/A/@N", ns[i])
          ENDFOR
        END
        """;

    [Fact]
    public async Task EightDocumentsInOneWrite_TheirFlagIsSetOnce_AfterAllEightAreStored()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration(Channel, Configuration);
        twin.Load(("wakes_open.src", OpenProgram), ("wakes_take.src", TakeProgram), ("wakes_take.dat", "DEFDAT wakes_take\n  DECL INT got\n  DECL INT ns[8]\nENDDAT\n"));
        Assert.Equal(KrlProgramState.Finished, twin.Run("wakes_open"));
        using var client = new TcpClient();
        await client.ConnectAsync(IPAddress.Loopback, twin.EkiPort(Channel));
        await EventuallyAsync(() => Flag(twin, 1), "the connection's ALIVE flag");
        long before = twin.InputsVersion;

        // One write of eight documents (one arrival on the loopback), then a second write whose flag says the first was read.
        string eight = string.Concat(Enumerable.Range(1, 8).Select(n => $"<DT><A N=\"{n}\"/></DT>"));
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(eight));
        await client.GetStream().WriteAsync("<B/>"u8.ToArray());
        await EventuallyAsync(() => Flag(twin, 3), "the second write's flag");

        // $FLAG[2] once for the eight (the base set it eight times), $FLAG[3] once: two moves, whether the two writes arrived
        // apart or together.
        Assert.Equal(2, twin.InputsVersion - before);
        Assert.True(Flag(twin, 2));
        Assert.Equal(KrlProgramState.Finished, twin.Run("wakes_take"));
        Assert.Equal(8, (int)twin.Modules["wakes_take"].Data["got"].Value);
        Assert.Equal(Enumerable.Range(1, 8), ((KrlArrayValue)twin.Modules["wakes_take"].Data["ns"].Value).ToObjects().Select(v => (int)v));
    }

    [Fact]
    public async Task DocumentsBeforeMalformedXml_InTheSameWrite_AreStoredAndFlagged_ThenTheConnectionCloses()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration(Channel, Configuration);
        twin.Load(("wakes_open.src", OpenProgram), ("wakes_take.src", TakeProgram), ("wakes_take.dat", "DEFDAT wakes_take\n  DECL INT got\n  DECL INT ns[8]\nENDDAT\n"));
        Assert.Equal(KrlProgramState.Finished, twin.Run("wakes_open"));
        using var client = new TcpClient();
        await client.ConnectAsync(IPAddress.Loopback, twin.EkiPort(Channel));
        await EventuallyAsync(() => Flag(twin, 1), "the connection's ALIVE flag");

        await client.GetStream().WriteAsync("<DT><A N=\"1\"/></DT><DT><A N=\"2\"/></DT></X>"u8.ToArray());
        await EventuallyAsync(() => !Flag(twin, 1), "the connection to close");

        Assert.True(Flag(twin, 2), "the two documents before the malformed part were stored without their flag");
        Assert.Equal(KrlProgramState.Finished, twin.Run("wakes_take"));
        Assert.Equal(2, (int)twin.Modules["wakes_take"].Data["got"].Value);
    }

    private static bool Flag(KrlTwinController twin, int number) => (bool)((KrlArrayValue)twin.Environment.System["$FLAG"].Value)[number - 1];
}
