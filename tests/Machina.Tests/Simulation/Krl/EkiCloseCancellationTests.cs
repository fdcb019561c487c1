using System.Net;
using System.Net.Sockets;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// EKI_Close writes what EKI_Send queued before it ends the connection. When the client reads nothing the writer cannot finish:
/// stopping the program must still end the wait, and the connection is ended all the same (before, EKI_Close waited without a
/// token and the program never stopped).
/// </summary>
public class EkiCloseCancellationTests
{
    private const string Channel = "machina_kuka_server";

    // Each send is a document of about 420 bytes; 40,000 of them (~17 MB) are more than the connection's buffers hold.
    private const string Program = """
        DEF close_stuck( )
          DECL EKI_STATUS ret
          DECL CHAR text[400]
          DECL INT i
          FOR i = 1 TO 400
            text[i] = "A"
          ENDFOR
          ret = EKI_Init("machina_kuka_server")
          ret = EKI_Open("machina_kuka_server")
          WAIT FOR $FLAG[1]
          ret = EKI_SetString("machina_kuka_server", "F/@Text", text[])
          FOR i = 1 TO 40000
            ret = EKI_Send("machina_kuka_server", "F")
          ENDFOR
          ret = EKI_Close("machina_kuka_server")
          WAIT FOR $FLAG[5]
        END
        """;

    private const int CloseLine = 15;

    [Fact]
    public async Task Close_WhileTheClientReadsNothing_EndsWhenTheProgramIsStopped()
    {
        using var twin = new KrlTwinController(new KrlTwinOptions());
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        using var stop = new CancellationTokenSource();
        try
        {
            twin.Reserve(Channel, listener);
            twin.AddEkiConfiguration(Channel, Machina.KukaDriverModules.Read(Channel + ".xml")
                .Replace("{{HOSTNAME}}", "127.0.0.1", StringComparison.Ordinal).Replace("{{PORT}}", "0", StringComparison.Ordinal));
            twin.Load(("close_stuck.src", Program));
            Task<KrlProgramState> run = Task.Run(() => twin.Run("close_stuck", stop.Token));
            // A client that never reads (and offers a small window): the channel's writer blocks once the buffers are full.
            using var client = new TcpClient { ReceiveBufferSize = 1024 };
            await client.ConnectAsync(IPAddress.Loopback, ((IPEndPoint)listener.LocalEndpoint).Port);
            await EventuallyAsync(() => twin.Line == CloseLine || run.IsCompleted, "the program to reach EKI_Close");
            Assert.False(run.IsCompleted, $"the program ended ({run.Status}) before EKI_Close could wait: its sends were written");

            stop.Cancel();
            Task ended = await Task.WhenAny(run, Task.Delay(Limit));
            Assert.True(ReferenceEquals(ended, run), "EKI_Close kept waiting for the writer after the program was stopped");
            Assert.Equal(KrlProgramState.Stopped, await run);
            Assert.False(twin.EkiConnected(Channel), "the stopped EKI_Close left the connection open");
        }
        finally
        {
            listener.Stop();
        }
    }
}
