using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// An EthernetKRL channel of the twin against hostile XML (issue 40): deep nesting was quadratic (240 KB: 31 s of processor
/// time while the real host was refused); now elements nest at most 64 deep and a document is at most the channel's BUFFSIZE,
/// the connection closes with the reason on the pendant, and the channel's next client is served.
/// </summary>
public sealed class EkiIntakeTests
{
    private const string Channel = "machina_kuka_server";

    private const string OpenProgram = """
        DEF intake_open( )
          DECL EKI_STATUS ret
          ret = EKI_Init("machina_kuka_server")
          ret = EKI_Open("machina_kuka_server")
        END
        """;

    [Fact]
    public void DeepNesting_240KB_ClosedAtOnce_WithTheReason()
    {
        string xml = new StringBuilder().Insert(0, "<a>", 80_000).ToString();
        var clock = Stopwatch.StartNew();

        string pendant = SendAndWaitForClose(xml);
        TimeSpan took = clock.Elapsed;

        Assert.Equal($"EthernetKRL {Channel}: received XML it cannot read (elements nested more than 64 deep); the connection is closed", pendant);
        Assert.True(took < TimeSpan.FromSeconds(5), $"closing took {took.TotalMilliseconds} ms");
    }

    [Fact]
    public void DocumentLongerThanBuffSize_ClosedWithTheReason()
    {
        // The server channel's BUFFSIZE is 65534 bytes: one document of 70,000 never completes.
        string xml = "<Robot><T>" + new string('x', 70_000) + "</T></Robot>";

        string pendant = SendAndWaitForClose(xml);

        Assert.Equal($"EthernetKRL {Channel}: received XML it cannot read (more than 65534 bytes without a complete document (the channel's BUFFSIZE Limit)); the connection is closed", pendant);
    }

    [Fact]
    public void Splitter_DocumentsAfterOneAnother_EachWithinTheSize_AllTaken()
    {
        var splitter = new EkiXmlSplitter(maxDocument: 40);
        var ended = new List<string>();
        splitter.Ended += (path, top) => ended.Add(path + (top ? "!" : ""));
        string one = "<A><B X=\"1\"/></A>"; // 17 characters

        for (int i = 0; i < 10; i++)
        {
            splitter.Append(one[..5]);
            splitter.Append(one[5..]);
        }

        Assert.Equal(20, ended.Count);
        Assert.Equal(["A/B", "A!"], ended.Take(2));
    }

    [Fact]
    public void Splitter_SameNamesUnderOtherElements_AnyChunking_TheSameItems()
    {
        const string Xml = "<?xml version=\"1.0\"?><DT><DR><A ID=\"1\" V=\"x &amp; y\"/><A ID='2'/></DR><B ID=\"3\">t</B></DT>\n"
            + "<DT><B ID=\"4\"/><DR><A V=\"5\" ID=\"6\"></A></DR></DT><A ID=\"7\"/>";
        string[] expected =
        [
            "DT/DR/A/@ID=1", "DT/DR/A/@V=x & y", "end DT/DR/A", "DT/DR/A/@ID=2", "end DT/DR/A", "end DT/DR", "DT/B/@ID=3", "DT/B=t",
            "end DT/B", "end DT!", "DT/B/@ID=4", "end DT/B", "DT/DR/A/@V=5", "DT/DR/A/@ID=6", "end DT/DR/A", "end DT/DR", "end DT!",
            "A/@ID=7", "end A!",
        ];
        for (int cut = 0; cut <= Xml.Length; cut++)
        {
            var splitter = new EkiXmlSplitter();
            var items = new List<string>();
            splitter.Value += (tag, value) => items.Add(tag + "=" + value);
            splitter.Ended += (path, top) => items.Add("end " + path + (top ? "!" : ""));

            splitter.Append(Xml[..cut]);
            splitter.Append(Xml.AsSpan(cut));

            Assert.Equal(expected, items);
        }
    }

    /// <summary>Opens the channel, sends <paramref name="xml"/> as a client; returns the pendant's last line once the twin closed the connection.</summary>
    private static string SendAndWaitForClose(string xml)
    {
        using var twin = new KrlTwinController(new KrlTwinOptions());
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        try
        {
            twin.Reserve(Channel, listener);
            twin.AddEkiConfiguration(Channel, Machina.KukaDriverModules.Read(Channel + ".xml")
                .Replace("{{HOSTNAME}}", "127.0.0.1", StringComparison.Ordinal).Replace("{{PORT}}", "0", StringComparison.Ordinal));
            twin.Load(("intake_open.src", OpenProgram));
            Assert.Equal(KrlProgramState.Finished, twin.Run("intake_open"));
            using var client = new TcpClient();
            client.Connect(IPAddress.Loopback, ((IPEndPoint)listener.LocalEndpoint).Port);
            client.ReceiveTimeout = (int)Limit.TotalMilliseconds;
            NetworkStream stream = client.GetStream();
            try
            {
                stream.Write(Encoding.UTF8.GetBytes(xml));
                Assert.Equal(0, stream.Read(new byte[16], 0, 16));
            }
            catch (IOException e) when (e.InnerException is SocketException { SocketErrorCode: not SocketError.TimedOut })
            {
                // Reset by the twin while bytes were still unread: closed too.
            }
            Assert.False(twin.EkiConnected(Channel));
            return twin.Pendant.Lines[^1];
        }
        finally
        {
            listener.Stop();
        }
    }
}
