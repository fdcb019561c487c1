using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EthernetKRL as published programs use it past XML elements (issue 43): EKI_Send of plain text (a course's XmlServer sends
/// "Comfirm" and a carriage return), binary data in raw mode (<c>&lt;RAW&gt;</c> STREAM and BYTE elements), and EKI_GetFrameArray.
/// </summary>
public class EkiTextRawFrameArrayTests
{
    private static string RobotClient(int port, string receive, string send) => $"""
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Server</TYPE><IP>127.0.0.1</IP><PORT>{port}</PORT></EXTERNAL>
            <INTERNAL><ALIVE Set_Flag="1" /></INTERNAL>
          </CONFIGURATION>
          <RECEIVE>{receive}</RECEIVE>
          <SEND>{send}</SEND>
        </ETHERNETKRL>
        """;

    /// <summary>Runs <paramref name="program"/> against a TCP server of the test's, which <paramref name="serve"/> talks to; returns what the server read until the robot closed.</summary>
    private static async Task<(KrlTwinController Twin, string Received)> RunAgainstServerAsync(
        string channel, Func<int, string> configuration, string name, string program, string data, Func<NetworkStream, StringBuilder, CancellationToken, Task> serve)
    {
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        try
        {
            var twin = new KrlTwinController();
            twin.AddEkiConfiguration(channel, configuration(((IPEndPoint)server.LocalEndpoint).Port));
            twin.Load(($"{name}.src", program), ($"{name}.dat", data));
            using var stop = new CancellationTokenSource(Limit);
            Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));
            using TcpClient robot = await server.AcceptTcpClientAsync(stop.Token);
            NetworkStream stream = robot.GetStream();
            var received = new StringBuilder();
            await serve(stream, received, stop.Token);
            var buffer = new byte[256];
            int count;
            while ((count = await stream.ReadAsync(buffer, stop.Token)) > 0)
            {
                received.Append(Encoding.Latin1.GetString(buffer, 0, count));
            }
            KrlProgramState state = await run.WaitAsync(Limit);
            Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
            return (twin, received.ToString());
        }
        finally
        {
            server.Stop();
        }
    }

    [Fact]
    public async Task EkiSend_OfPlainText_WritesTheTextAsItIs()
    {
        const string program = """
            DEF text( )
              DECL EKI_STATUS ret
              ret = EKI_Init("XmlServer")
              ret = EKI_Open("XmlServer")
              ret = EKI_Send("XmlServer", "Comfirm")
              ret = EKI_Send("XmlServer", EOL[])
              sent = ret.Msg_No
              ret = EKI_Close("XmlServer")
            END
            """;
        (KrlTwinController twin, string received) = await RunAgainstServerAsync("XmlServer",
            port => RobotClient(port, "<XML><ELEMENT Tag=\"Data/Direction\" Type=\"STRING\" Set_Flag=\"2\" /></XML>", "<XML></XML>"),
            "text", program, "DEFDAT text\n  DECL CHAR EOL[1]\n  EOL[1] = 13\n  INT sent = -1\nENDDAT\n", (_, _, _) => Task.CompletedTask);
        using (twin)
        {
            Assert.Equal("Comfirm\r", received);
            Assert.Equal(0, (int)twin.Modules["text"].Data["sent"].Value);
        }
    }

    [Fact]
    public async Task RawStream_ReceivesARecordUpToItsEndString_AndSendsWithIt()
    {
        const string program = """
            DEF raw( )
              DECL EKI_STATUS ret
              ret = EKI_Init("Raw")
              ret = EKI_Open("Raw")
              ret = EKI_Send("Raw", "HELLO")
              WAIT FOR $FLAG[2]
              ret = EKI_GetString("Raw", "Buffer", line[])
              read = ret.Read
              ret = EKI_Send("Raw", line[])
              ret = EKI_Close("Raw")
            END
            """;
        (KrlTwinController twin, string received) = await RunAgainstServerAsync("Raw",
            port => RobotClient(port, "<RAW><ELEMENT Tag=\"Buffer\" Type=\"STREAM\" EOS=\"13,10\" Size=\"64\" Set_Flag=\"2\" /></RAW>",
                "<RAW><ELEMENT Tag=\"Out\" Type=\"STREAM\" EOS=\"59\" /></RAW>"),
            "raw", program, "DEFDAT raw\n  DECL CHAR line[16]\n  INT read = 0\nENDDAT\n",
            async (stream, received, token) =>
            {
                var buffer = new byte[64];
                while (!received.ToString().Contains(';', StringComparison.Ordinal))
                {
                    int count = await stream.ReadAsync(buffer, token);
                    Assert.True(count > 0, "the robot closed the connection before it sent");
                    received.Append(Encoding.Latin1.GetString(buffer, 0, count));
                }
                await stream.WriteAsync(Encoding.Latin1.GetBytes("PING\r\n"), token);
            });
        using (twin)
        {
            Assert.Equal("HELLO;PING;", received);
            Assert.Equal("PING", KrlValues.Text((KrlArrayValue)twin.Modules["raw"].Data["line"].Value));
            Assert.Equal(1, (int)twin.Modules["raw"].Data["read"].Value);
        }
    }

    [Fact]
    public void RawByte_CutsFixedRecords_AndSendsExactlyItsSize()
    {
        var element = new EkiRawElement("Buffer", Stream: false, Size: 4, EndStrings: [], SetFlag: 0);
        var splitter = new EkiRawSplitter(element);

        Assert.Equal(new[] { "ABCD", "EFGH" }, splitter.Append("ABCDEFGHIJ"u8));
        Assert.Equal(new[] { "IJKL" }, splitter.Append("KL"u8));
        Assert.Equal(new byte[] { (byte)'X', (byte)'Y', 0, 0 }, EkiRawSplitter.Record(element, "XY"));
        Assert.Equal("ABCD"u8.ToArray(), EkiRawSplitter.Record(element, "ABCDEF"));
    }

    [Theory]
    [InlineData("<RAW><ELEMENT Tag=\"B\" Type=\"BYTE\" /></RAW>", "the RAW ELEMENT B of Bad.xml needs a Size of 1 to 3600 bytes")]
    [InlineData("<RAW><ELEMENT Tag=\"B\" Type=\"STREAM\" /></RAW>", "the RAW ELEMENT B of Bad.xml is a STREAM without an end string (EOS)")]
    [InlineData("<RAW><ELEMENT Tag=\"B\" Type=\"WORD\" Size=\"2\" /></RAW>", "the RAW ELEMENT B of Bad.xml has Type \"WORD\": BYTE (fixed length) or STREAM (with an end string)")]
    [InlineData("<RAW><ELEMENT Tag=\"B\" Type=\"BYTE\" Size=\"2\" /><ELEMENT Tag=\"C\" Type=\"BYTE\" Size=\"3\" /></RAW>", "the configuration Bad.xml has 2 RAW elements in <RECEIVE>: binary data has one memory, so one element")]
    public void RawConfiguration_ThePackageWouldRefuse_IsRefusedWithWhy(string receive, string reason)
    {
        FormatException ex = Assert.Throws<FormatException>(() => EkiConfiguration.Parse("Bad", RobotClient(1, receive, "")));

        Assert.Equal(reason, ex.Message);
    }

    private const string FramesConfiguration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL><IP>127.0.0.1</IP><PORT>0</PORT><PROTOCOL>UDP</PROTOCOL></INTERNAL>
          </CONFIGURATION>
          <RECEIVE><XML><ELEMENT Tag="Path/P" Type="FRAME" /><ELEMENT Tag="Path" Set_Flag="2" /></XML></RECEIVE>
          <SEND><XML><ELEMENT Tag="Ack/@N" /></XML></SEND>
        </ETHERNETKRL>
        """;

    private const string FramesProgram = """
        DEF frames( )
          DECL EKI_STATUS ret
          DECL FRAME path[3]
          ret = EKI_Init("Frames")
          ret = EKI_Open("Frames")
          WAIT FOR $FLAG[2]
          ret = EKI_GetFrameArray("Frames", "Path/P", path[])
          read = ret.Read
          left = ret.Buff
          sum = path[1].X + path[2].Y * 10 + path[2].C * 100
          ret = EKI_SetInt("Frames", "Ack/@N", read)
          ret = EKI_Send("Frames", "Ack")
          ret = EKI_Close("Frames")
        END
        """;

    [Fact]
    public async Task GetFrameArray_FillsTheArrayFromTheFrameMemory()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Frames", FramesConfiguration);
        twin.Load(("frames.src", FramesProgram), ("frames.dat", "DEFDAT frames\n  INT read = 0\n  INT left = -1\n  REAL sum = 0\nENDDAT\n"));

        (KrlProgramState state, string answer) = await EkiUdpExchange.RunAsync(twin, "Frames",
            "<Path><P X=\"1\" Y=\"2\" Z=\"3\" A=\"4\" B=\"5\" C=\"6\"/><P X=\"10\" Y=\"20\" C=\"-30\"/></Path>");

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("<Ack N=\"2\" />", answer);
        Assert.Equal(0, (int)twin.Modules["frames"].Data["left"].Value);
        Assert.Equal(1 + 200 - 3000, (double)twin.Modules["frames"].Data["sum"].Value, 9);
    }

    [Fact]
    public void GetFrameArray_OfAnElementThatIsNoFrame_StopsTheProgramWithWhy()
    {
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Frames", FramesConfiguration);
        twin.Load(("frames.src", "DEF frames( )\n  DECL EKI_STATUS ret\n  DECL FRAME path[3]\n  ret = EKI_Init(\"Frames\")\n  ret = EKI_GetFrameArray(\"Frames\", \"Path\", path[])\nEND\n"));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.Equal("EthernetKRL: EKI_GetFrameArray reads an element of Type=\"FRAME\"; the channel Frames receives no FRAME element Path (frames.src, line 5)", twin.Error);
    }
}
