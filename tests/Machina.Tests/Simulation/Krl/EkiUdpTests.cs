using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EthernetKRL over UDP (issue 43): a channel whose XML says PROTOCOL UDP exchanges datagrams with a client, its ALIVE flag up from
/// the first datagram; EKI_Send writes nested SEND elements as their tags say.
/// </summary>
public class EkiUdpTests
{
    private const string Channel = "UdpJointServer";

    private const string Configuration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL>
              <ENVIRONMENT>Program</ENVIRONMENT>
              <BUFFERING Limit="4" />
              <ALIVE Set_Flag="1" />
              <IP>127.0.0.1</IP>
              <PORT>0</PORT>
              <PROTOCOL>UDP</PROTOCOL>
            </INTERNAL>
          </CONFIGURATION>
          <RECEIVE>
            <XML>
              <ELEMENT Tag="Cmd/Pos/@A1" Type="REAL" />
              <ELEMENT Tag="Cmd/Pos/@A2" Type="REAL" />
              <ELEMENT Tag="Cmd" Set_Flag="2" />
            </XML>
          </RECEIVE>
          <SEND>
            <XML>
              <ELEMENT Tag="State/Pos/@A1" />
              <ELEMENT Tag="State/Pos/@A2" />
              <ELEMENT Tag="State/@Buffered" />
            </XML>
          </SEND>
        </ETHERNETKRL>
        """;

    private const string Program = """
        DEF udp_server( )
          DECL EKI_STATUS ret
          DECL REAL a1, a2
          ret = EKI_Init("UdpJointServer")
          ret = EKI_Open("UdpJointServer")
          WAIT FOR $FLAG[2]
          $FLAG[2] = FALSE
          ret = EKI_GetReal("UdpJointServer", "Cmd/Pos/@A1", a1)
          ret = EKI_GetReal("UdpJointServer", "Cmd/Pos/@A2", a2)
          PTP {AXIS: A1 a1, A2 a2, A3 90, A4 0, A5 30, A6 0}
          ret = EKI_CheckBuffer("UdpJointServer", "Cmd/Pos/@A1")
          ret = EKI_SetReal("UdpJointServer", "State/Pos/@A1", $AXIS_ACT.A1)
          ret = EKI_SetReal("UdpJointServer", "State/Pos/@A2", $AXIS_ACT.A2)
          ret = EKI_SetInt("UdpJointServer", "State/@Buffered", ret.Buff)
          ret = EKI_Send("UdpJointServer", "State")
          WAIT FOR $FLAG[2]
          ret = EKI_Close("UdpJointServer")
        END
        """;

    [Fact]
    public async Task UdpServerChannel_ExchangesDatagramsWithAClient()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration(Channel, Configuration);
        twin.Load(("udp_server.src", Program));
        using var stop = new CancellationTokenSource(Limit);
        Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));
        await EventuallyAsync(() => twin.EkiPort(Channel) > 0 || run.IsCompleted, "the channel to be open");
        int port = twin.EkiPort(Channel);
        Assert.False(Alive(twin), "the ALIVE flag is up before any datagram came");

        using var client = new UdpClient(new IPEndPoint(IPAddress.Loopback, 0));
        byte[] command = Encoding.UTF8.GetBytes("<Cmd><Pos A1=\"12.5\" A2=\"-75\" /></Cmd>");
        await client.SendAsync(command, new IPEndPoint(IPAddress.Loopback, port));
        UdpReceiveResult answer = await client.ReceiveAsync(stop.Token).AsTask().WaitAsync(Limit);

        Assert.Equal("<State Buffered=\"0\"><Pos A1=\"12.5\" A2=\"-75\" /></State>", Encoding.UTF8.GetString(answer.Buffer));
        Assert.Equal(port, answer.RemoteEndPoint.Port);
        Assert.True(Alive(twin));
        await client.SendAsync(Encoding.UTF8.GetBytes("<Cmd />"), new IPEndPoint(IPAddress.Loopback, port));
        KrlProgramState state = await run.WaitAsync(Limit);
        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.False(Alive(twin), "EKI_Close leaves the ALIVE flag up");
        Assert.Equal(12.5, twin.Arm.Joints.J1, 6);
    }

    [Fact]
    public async Task ClearBuffer_DropsTheElementsBelowATag_AndConfirmRuns()
    {
        const string program = """
            DEF clear_buffer( )
              DECL EKI_STATUS ret
              ret = EKI_Init("UdpJointServer")
              ret = EKI_Open("UdpJointServer")
              WAIT FOR $FLAG[2]
              ret = EKI_CheckBuffer("UdpJointServer", "Cmd/Pos/@A1")
              before = ret.Buff
              ret = EKI_ClearBuffer("UdpJointServer", "Cmd")
              ret = EKI_CheckBuffer("UdpJointServer", "Cmd/Pos/@A2")
              after = ret.Buff
              CONFIRM 0
              ret = EKI_Clear("UdpJointServer")
            END
            """;
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration(Channel, Configuration);
        twin.Load(("clear_buffer.src", program), ("clear_buffer.dat", "DEFDAT clear_buffer\n  INT before = -1\n  INT after = -1\nENDDAT\n"));
        using var stop = new CancellationTokenSource(Limit);
        Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));
        await EventuallyAsync(() => twin.EkiPort(Channel) > 0 || run.IsCompleted, "the channel to be open");

        using var client = new UdpClient(new IPEndPoint(IPAddress.Loopback, 0));
        await client.SendAsync(Encoding.UTF8.GetBytes("<Cmd><Pos A1=\"1\" A2=\"2\" /></Cmd>"), new IPEndPoint(IPAddress.Loopback, twin.EkiPort(Channel)));
        KrlProgramState state = await run.WaitAsync(Limit);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(1, (int)twin.Modules["clear_buffer"].Data["before"].Value);
        Assert.Equal(0, (int)twin.Modules["clear_buffer"].Data["after"].Value);
    }

    [Fact]
    public void Configuration_ReadsTheProtocol_AndRefusesOneEthernetKrlDoesNotSpeak()
    {
        Assert.True(EkiConfiguration.Parse(Channel, Configuration).Udp);
        Assert.False(EkiConfiguration.Parse(Channel, Configuration.Replace("<PROTOCOL>UDP</PROTOCOL>", "", StringComparison.Ordinal)).Udp);
        FormatException ex = Assert.Throws<FormatException>(() => EkiConfiguration.Parse(Channel, Configuration.Replace(">UDP<", ">SCTP<", StringComparison.Ordinal)));
        Assert.Equal("the configuration UdpJointServer.xml has PROTOCOL \"SCTP\": EthernetKRL speaks TCP or UDP", ex.Message);
    }

    [Fact]
    public void SendDocument_NestsElementsAsTheirTagsSay_AndKeepsAFlatElementAsBefore()
    {
        var values = new Dictionary<string, string> { ["R/@A"] = "1", ["R/@B"] = "x<y", ["S/P/@A1"] = "2", ["S/T"] = "ok" };
        string[] tags = ["R/@A", "R/@B", "R/@C", "S/P/@A1", "S/P/@A2", "S/T", "S/Empty"];

        Assert.Equal("<R A=\"1\" B=\"x&lt;y\" />", EkiSendDocument.Write("R", tags, values));
        Assert.Equal("<S><P A1=\"2\" /><T>ok</T><Empty /></S>", EkiSendDocument.Write("S", tags, values));
    }

    private static bool Alive(KrlTwinController twin) => (bool)((KrlArrayValue)twin.Environment.System["$FLAG"].Value)[0];
}
