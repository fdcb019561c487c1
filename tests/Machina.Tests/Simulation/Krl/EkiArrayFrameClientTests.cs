using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EthernetKRL functions and roles published programs use (issue 43): EKI_GetIntArray (and the Real and Bool ones) fill an array
/// from a memory, EKI_GetFrame and EKI_SetFrame read and write a FRAME element's X Y Z A B C attributes, and a TCP channel with
/// the robot as client (TYPE Server) connects to the external server at EKI_Open.
/// </summary>
public class EkiArrayFrameClientTests
{
    private const string UdpConfiguration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL><IP>127.0.0.1</IP><PORT>0</PORT><PROTOCOL>UDP</PROTOCOL></INTERNAL>
          </CONFIGURATION>
          <RECEIVE>
            <XML>
              <ELEMENT Tag="Cmd/V/@Id" Type="INT" />
              <ELEMENT Tag="Cmd/Pos" Type="FRAME" />
              <ELEMENT Tag="Cmd" Set_Flag="2" />
            </XML>
          </RECEIVE>
          <SEND>
            <XML>
              <ELEMENT Tag="State/@Read" />
              <ELEMENT Tag="State/@Left" />
              <ELEMENT Tag="State/Pos" Type="FRAME" />
            </XML>
          </SEND>
        </ETHERNETKRL>
        """;

    private const string ArrayProgram = """
        DEF arrays( )
          DECL EKI_STATUS ret
          DECL INT ids[4]
          DECL FRAME target
          INT read, left
          ret = EKI_Init("Arrays")
          ret = EKI_Open("Arrays")
          WAIT FOR $FLAG[2]
          ret = EKI_GetIntArray("Arrays", "Cmd/V/@Id", ids[])
          read = ret.Read
          left = ret.Buff
          ret = EKI_GetFrame("Arrays", "Cmd/Pos", target)
          target.Z = target.Z + 1
          ret = EKI_SetFrame("Arrays", "State/Pos", target)
          ret = EKI_SetInt("Arrays", "State/@Read", read)
          ret = EKI_SetInt("Arrays", "State/@Left", left)
          ret = EKI_Send("Arrays", "State")
          lastIds = ids[1] * 1000 + ids[2] * 100 + ids[3] * 10 + ids[4]
          ret = EKI_Close("Arrays")
        END
        """;

    [Fact]
    public async Task GetIntArray_FillsTheArray_AndGetFrameSetFrame_ReadAndWriteTheAttributes()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Arrays", UdpConfiguration);
        twin.Load(("arrays.src", ArrayProgram), ("arrays.dat", "DEFDAT arrays\n  INT lastIds = 0\nENDDAT\n"));

        (KrlProgramState state, string answer) = await EkiUdpExchange.RunAsync(twin, "Arrays",
            "<Cmd><V Id=\"5\"/><V Id=\"6\"/><V Id=\"7\"/><V Id=\"8\"/><V Id=\"9\"/><Pos X=\"1\" Y=\"2\" Z=\"3\" A=\"4\" B=\"5\" C=\"6\"/></Cmd>");

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("<State Read=\"4\" Left=\"1\"><Pos X=\"1\" Y=\"2\" Z=\"4\" A=\"4\" B=\"5\" C=\"6\" /></State>", answer);
        Assert.Equal(5678, (int)twin.Modules["arrays"].Data["lastIds"].Value);
    }

    private static string ClientConfiguration(int port) => $"""
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Server</TYPE><IP>127.0.0.1</IP><PORT>{port}</PORT></EXTERNAL>
            <INTERNAL><ALIVE Set_Flag="1" /></INTERNAL>
          </CONFIGURATION>
          <RECEIVE><XML><ELEMENT Tag="Cmd/@N" Type="INT" /><ELEMENT Tag="Cmd" Set_Flag="2" /></XML></RECEIVE>
          <SEND><XML><ELEMENT Tag="Hello/@N" /></XML></SEND>
        </ETHERNETKRL>
        """;

    private const string ClientProgram = """
        DEF client( )
          DECL EKI_STATUS ret
          ret = EKI_Init("ToServer")
          ret = EKI_Open("ToServer")
          alive = $FLAG[1]
          ret = EKI_SetInt("ToServer", "Hello/@N", 1)
          ret = EKI_Send("ToServer", "Hello")
          WAIT FOR $FLAG[2]
          ret = EKI_GetInt("ToServer", "Cmd/@N", n)
          ret = EKI_Close("ToServer")
        END
        """;

    [Fact]
    public async Task RobotAsTcpClient_ConnectsAtOpen_SendsAndReceives()
    {
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        try
        {
            using var twin = new KrlTwinController();
            twin.AddEkiConfiguration("ToServer", ClientConfiguration(((IPEndPoint)server.LocalEndpoint).Port));
            twin.Load(("client.src", ClientProgram), ("client.dat", "DEFDAT client\n  BOOL alive = FALSE\n  INT n = 0\nENDDAT\n"));
            using var stop = new CancellationTokenSource(Limit);
            Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));

            using TcpClient robot = await server.AcceptTcpClientAsync(stop.Token);
            NetworkStream stream = robot.GetStream();
            var received = new StringBuilder();
            var buffer = new byte[256];
            while (!received.ToString().Contains("/>", StringComparison.Ordinal))
            {
                int count = await stream.ReadAsync(buffer, stop.Token);
                Assert.True(count > 0, "the robot closed the connection before it sent");
                received.Append(Encoding.UTF8.GetString(buffer, 0, count));
            }
            await stream.WriteAsync(Encoding.UTF8.GetBytes("<Cmd N=\"42\" />"), stop.Token);
            KrlProgramState state = await run.WaitAsync(Limit);

            Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
            Assert.Equal("<Hello N=\"1\" />", received.ToString());
            Assert.True((bool)twin.Modules["client"].Data["alive"].Value, "the ALIVE flag was down right after EKI_Open");
            Assert.Equal(42, (int)twin.Modules["client"].Data["n"].Value);
        }
        finally
        {
            server.Stop();
        }
    }

    [Fact]
    public void RobotAsTcpClient_WithNoServer_StopsTheProgramAtOpen_WithTheAddress()
    {
        var probe = new TcpListener(IPAddress.Loopback, 0);
        probe.Start();
        int port = ((IPEndPoint)probe.LocalEndpoint).Port;
        probe.Stop(); // nothing listens there now: the connection is refused

        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("ToServer", ClientConfiguration(port));
        twin.Load(("client.src", ClientProgram), ("client.dat", "DEFDAT client\n  BOOL alive = FALSE\n  INT n = 0\nENDDAT\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.StartsWith($"EthernetKRL: the channel ToServer cannot connect to the server 127.0.0.1:{port} (", twin.Error, StringComparison.Ordinal);
        Assert.EndsWith("(client.src, line 4)", twin.Error, StringComparison.Ordinal);
    }
}
