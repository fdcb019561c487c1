using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// A raw (<c>&lt;RAW&gt;</c>) channel's EKI_Send through the twin's seam (how <c>machina sim kuka</c> runs every channel): the record
/// reaches the seam and the client as its bytes, one byte per CHAR. Before, the seam was handed the record read as Latin-1 text and
/// written as UTF-8, so a CHAR from 128 on (here 233) reached the client as two bytes.
/// </summary>
public sealed class EkiRawSeamSendTests
{
    /// <summary>Forwards every send to the channel's connection and keeps the bytes it was handed.</summary>
    private sealed class RecordingSeam : IEkiSeam
    {
        private readonly object _gate = new();
        private readonly List<byte[]> _sent = [];

        public byte[][] Sent
        {
            get
            {
                lock (_gate)
                {
                    return [.. _sent];
                }
            }
        }

        public bool Accepted(EkiChannel channel, TcpClient client) => true;

        public void Received(EkiChannel channel, ReadOnlySpan<(string Tag, string Value)> values)
        {
        }

        public bool Send(EkiChannel channel, string root, byte[] document)
        {
            lock (_gate)
            {
                _sent.Add(document);
            }
            return channel.SendDirect(document);
        }

        public void Closed(EkiChannel channel, TcpClient client)
        {
        }
    }

    [Fact]
    public async Task RawSend_ThroughTheSeam_WritesOneBytePerChar()
    {
        const string program = """
            DEF rawseam( )
              DECL EKI_STATUS ret
              ret = EKI_Init("Raw")
              ret = EKI_Open("Raw")
              ret = EKI_Send("Raw", data[])
              ret = EKI_Close("Raw")
            END
            """;
        const string data = "DEFDAT rawseam\n  DECL CHAR data[3]\n  data[1] = 72\n  data[2] = 233\n  data[3] = 127\nENDDAT\n";
        var server = new TcpListener(IPAddress.Loopback, 0);
        server.Start();
        try
        {
            var seam = new RecordingSeam();
            using var twin = new KrlTwinController(new KrlTwinOptions { Seam = seam });
            twin.AddEkiConfiguration("Raw", $"""
                <ETHERNETKRL>
                  <CONFIGURATION>
                    <EXTERNAL><TYPE>Server</TYPE><IP>127.0.0.1</IP><PORT>{((IPEndPoint)server.LocalEndpoint).Port}</PORT></EXTERNAL>
                    <INTERNAL><ALIVE Set_Flag="1" /></INTERNAL>
                  </CONFIGURATION>
                  <RECEIVE><RAW><ELEMENT Tag="In" Type="STREAM" EOS="59" /></RAW></RECEIVE>
                  <SEND><RAW><ELEMENT Tag="Out" Type="STREAM" EOS="59" /></RAW></SEND>
                </ETHERNETKRL>
                """);
            twin.Load(("rawseam.src", program), ("rawseam.dat", data));
            using var stop = new CancellationTokenSource(Limit);
            Task<KrlProgramState> run = Task.Run(() => twin.Run(null, stop.Token));
            using TcpClient robot = await server.AcceptTcpClientAsync(stop.Token);
            var received = new List<byte>();
            var buffer = new byte[64];
            int count;
            while ((count = await robot.GetStream().ReadAsync(buffer, stop.Token)) > 0)
            {
                received.AddRange(buffer.AsSpan(0, count).ToArray());
            }
            KrlProgramState state = await run.WaitAsync(Limit);

            Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
            Assert.Equal(new byte[] { 72, 233, 127, 59 }, Assert.Single(seam.Sent));
            Assert.Equal(new byte[] { 72, 233, 127, 59 }, received.ToArray());
        }
        finally
        {
            server.Stop();
        }
    }
}
